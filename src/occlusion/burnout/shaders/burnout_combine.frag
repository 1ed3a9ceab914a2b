#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Burnout chain, pass 3: the binary sub-cell mask into the 14 x 14 grid. A cell holds
// (visible x weight, weight): weight = its share of sub-cells in the disc x cos^3 of its
// centre's angle to the axis (solid angle) x the chain's compensation, so that the uneven
// bilinear taps of 14 -> 8 (source texels weigh 1/8 to 7/8 there) cancel and R / G at the end
// of the chain is the disc's visible share.
layout(binding = 0) uniform sampler2D mask;
uniform int subCells;              // sub-cells per cell side
uniform vec2 regionOrigin;         // GL pixels
uniform float cellSize;            // pixels per cell
uniform float compensation[14];    // per grid column / row: min chain weight / its weight
out vec4 fragColor;
void main() {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    float visible = 0.0, disc = 0.0;
    for (int j = 0; j < subCells; ++j) {
        for (int i = 0; i < subCells; ++i) {
            vec4 m = texelFetch(mask, cell * subCells + ivec2(i, j), 0);
            disc += m.g;
            visible += (1.0 - m.r) * m.g;
        }
    }
    float cosTheta = dot(rayThrough(regionOrigin + (vec2(cell) + 0.5) * cellSize), camForward);
    float weight = cosTheta * cosTheta * cosTheta * compensation[cell.x] * compensation[cell.y] / float(subCells * subCells);
    fragColor = vec4(visible * weight, disc * weight, 0.0, 1.0);
}
