#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The element's premultiplied image x the light's tinted brightness: colour scales, coverage
// (alpha) does not, as in renderFlare. The engine adds it to the application's linear HDR
// colour with the destination's alpha kept (GL_ZERO, GL_ONE); GpuSpriteFlare's Screen and
// Over elements composite with that alpha.
layout(BINDING(12, 8)) uniform sampler2D element;
layout(location = 0) in vec2 uv;
layout(location = 1) flat in vec3 tint;
layout(location = 0) out vec4 fragColor;
void main() {
    vec4 s = texture(element, uv);
    fragColor = vec4(s.rgb * tint, s.a);
}
