#version 450 core
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
out float sky;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef MULTISAMPLE
    int n = 0;
    for (int i = 0; i < sampleCount; ++i)
        if (texelFetch(depthSamples, p, i).r >= 1.0) ++n;
    sky = float(n) / float(sampleCount);
#else
    sky = texelFetch(depth, p, 0).r >= 1.0 ? 1.0 : 0.0;
#endif
}
