#version 450
// SPDX-License-Identifier: Apache-2.0
// The element's premultiplied sprite x the record's colour: colour scales, alpha does not (as
// light_flare.frag). Blend it additively into the linear HDR colour: rgb ONE, ONE; alpha ZERO,
// ONE (the destination's alpha kept). Binding 2: the sprite, sampled linearly, clamped.
#ifdef VULKAN
#define BINDING(n) set = 0, binding = n
#else
#define BINDING(n) binding = n
#endif

layout(BINDING(2)) uniform sampler2D sprite;
layout(location = 0) in vec2 uv;
layout(location = 1) flat in vec3 tint;
layout(location = 0) out vec4 fragColor;

void main() {
    vec4 s = texture(sprite, uv);
    fragColor = vec4(s.rgb * tint, s.a);
}
