#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Burnout chain, passes 4-7: one bilinear tap per destination texel (14 -> 8 -> 4 -> 2 -> 1),
// as the PSP's texture unit does it. Not a box filter: at 14 -> 8 the taps weigh the source
// texels unevenly (1/8 to 7/8), which the combine pass compensates. 16-bit targets keep the
// small weighted values from rounding away.
layout(binding = 0) uniform sampler2D source;
uniform vec2 destinationSize;
out vec4 fragColor;
void main() { fragColor = texture(source, gl_FragCoord.xy / destinationSize); }
