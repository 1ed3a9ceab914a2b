#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Coverage = visible / disc, from a 1x1 RG sum, into the 1x1 R32F coverage texture.
layout(binding = 0) uniform sampler2D sums;
out vec4 fragColor;
void main() {
    vec4 s = texelFetch(sums, ivec2(0), 0);
    fragColor = vec4(s.g > 0.0 ? s.r / s.g : 0.0);
}
