#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The element's premultiplied image x the light's tinted brightness, added to the
// application's linear HDR colour (alpha untouched).
layout(binding = 12) uniform sampler2D element;
in vec2 uv;
flat in vec3 tint;
out vec4 fragColor;
void main() {
    vec4 s = texture(element, uv);
    fragColor = vec4(s.rgb * tint, 0.0);
}
