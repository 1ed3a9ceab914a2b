#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The share of each pixel through which the sky (and so the sun) is seen: with MSAA the
// fraction of the pixel's depth samples left at the cleared far value 1, otherwise 0 or 1.
// It gives the single-sample screen methods (readback, pbo) sub-pixel occluder edges: a pole
// half a pixel wide hides half of each pixel it crosses instead of all or nothing.
#ifdef MULTISAMPLE
layout(binding = 0) uniform sampler2DMS depthSamples;
uniform int sampleCount;
#else
layout(binding = 0) uniform sampler2D depth;
#endif
uniform float lightDepth;  // 1 (the cleared far value) for the sun; a sphere light's near side
out float sky;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef MULTISAMPLE
    int n = 0;
    for (int i = 0; i < sampleCount; ++i)
        if (texelFetch(depthSamples, p, i).r >= lightDepth) ++n;
    sky = float(n) / float(sampleCount);
#else
    sky = texelFetch(depth, p, 0).r >= lightDepth ? 1.0 : 0.0;
#endif
}
