#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Burnout chain, pass 1: the white rectangle, drawn without depth test over the sun's square.
// The square's 14 x 14 cells are split into sub-cells (4 x 4 each), the mask's texels. Each
// sub-cell also lays the frame's depth at its centre into the mask's own depth buffer (the PSP
// draws straight over its frame buffer; here the frame's depth, read per MSAA sample where it
// has them, is copied), and marks in G whether its centre is in the disc and on screen.
uniform vec2 regionOrigin;  // GL pixels, bottom-left of the square
uniform float subCellSize;  // pixels per sub-cell
out vec4 fragColor;
void main() {
    vec2 at = regionOrigin + gl_FragCoord.xy * subCellSize;  // gl_FragCoord is the texel centre
    bool onScreen = all(greaterThanEqual(at, vec2(0.0))) && all(lessThan(at, frameSize));
    bool disc = onScreen && inSunDisc(rayThrough(at));
    gl_FragDepth = onScreen ? frameDepthAt(at) : 0.0;
    fragColor = vec4(1.0, disc ? 1.0 : 0.0, 0.0, 1.0);
}
