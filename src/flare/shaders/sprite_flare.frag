#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The element's premultiplied image (rendered at intensity 1 x its own and the preset's
// intensity) scaled by the flare's intensity: colour scales, coverage (alpha) does not, as in
// renderFlare, where the intensity multiplies the element's colours only.
layout(binding = 0) uniform sampler2D element;
in vec2 uv;
flat in float intensity;
out vec4 fragColor;
void main() {
    vec4 s = texture(element, uv);
    fragColor = vec4(s.rgb * intensity, s.a);
}
