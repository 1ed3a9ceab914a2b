#version 450 core
// SPDX-License-Identifier: Apache-2.0
// texture-mask-screen: the sun map built from the main frame's depth instead of a re-render.
// Each texel is split into 4 x 4 sub-texels whose rays (through the sun camera, below) are
// projected into the main frame; a sub-texel is sun when the frame shows sky there (depth
// at the far plane, read per MSAA sample where the frame has them: frame_depth.glsl). R is
// the texel's share of sub-texels in the disc, on screen and sky, G its share in the disc and
// on screen, so off-screen parts drop out of the normalisation and rim texels count by area.
uniform vec3 mapRight, mapUp, mapForward;  // the sun camera
uniform float mapTanHalf;
uniform float mapSize;
out vec4 fragColor;
void main() {
    const int kSub = 4;
    int disc = 0, sky = 0;
    for (int j = 0; j < kSub; ++j) {
        for (int i = 0; i < kSub; ++i) {
            vec2 at = floor(gl_FragCoord.xy) + (vec2(i, j) + 0.5) / float(kSub);
            vec2 ndc = at / mapSize * 2.0 - 1.0;
            vec3 d = normalize(mapForward + (mapRight * ndc.x + mapUp * ndc.y) * mapTanHalf);
            if (!inSunDisc(d)) continue;
            float z = dot(d, camForward);
            if (z <= 0.0) continue;
            vec2 pixel = (vec2(dot(d, camRight), dot(d, camUp)) / z / tanHalfFov * 0.5 + 0.5) * frameSize;
            if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, frameSize))) continue;
            ++disc;
            if (frameDepthAt(pixel) >= lightDepth) ++sky;
        }
    }
    float n = float(kSub * kSub);
    fragColor = vec4(float(sky) / n, float(disc) / n, 0.0, 1.0);
}
