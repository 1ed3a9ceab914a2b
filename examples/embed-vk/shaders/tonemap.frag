#version 450
// SPDX-License-Identifier: Apache-2.0
// The application's own tone map, after flarekit added the flares in linear HDR.
layout(location = 0) in vec2 ndc;
layout(set = 0, binding = 0) uniform sampler2D hdr;
layout(location = 0) out vec4 fragColor;
void main() {
    vec3 x = texture(hdr, ndc * 0.5 + 0.5).rgb * 0.6;
    vec3 mapped = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);  // Narkowicz's ACES fit
    fragColor = vec4(pow(clamp(mapped, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
