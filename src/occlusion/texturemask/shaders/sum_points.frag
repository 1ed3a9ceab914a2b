#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Each sample adds its sun-map value times `unit`: 1/255 (the seed's 0x01010101 modulation)
// for one texel, 4/255 for a bilinear 2x2 average, so an 8-bit target counts exactly.
in vec2 uv;
uniform sampler2D sunMap;
uniform float unit;
out vec4 fragColor;
void main() { fragColor = texture(sunMap, uv) * unit; }
