// SPDX-License-Identifier: Apache-2.0
// The main frame's depth at a point (GL pixel units), for passes that sample it finer than a
// pixel (texture-mask-screen's sub-texels, burnout's sub-cells). With MSAA the point reads the
// depth sample of its pixel nearest to it, so occluder edges are resolved to the sample
// pattern, not the pixel. FrameDepth.cpp binds the texture and the sample positions.
#ifdef MULTISAMPLE
layout(binding = 0) uniform sampler2DMS frameDepthSamples;
uniform int frameSampleCount;
uniform vec2 frameSamplePositions[16];  // within the pixel, [0, 1)^2 (glGetMultisamplefv)
float frameDepthAt(vec2 p) {
    vec2 inPixel = fract(p);
    int nearest = 0;
    float best = 4.0;
    for (int i = 0; i < frameSampleCount; ++i) {
        vec2 d = frameSamplePositions[i] - inPixel;
        if (dot(d, d) < best) best = dot(d, d), nearest = i;
    }
    return texelFetch(frameDepthSamples, ivec2(p), nearest).r;
}
#else
layout(binding = 0) uniform sampler2D frameDepth;
float frameDepthAt(vec2 p) { return texelFetch(frameDepth, ivec2(p), 0).r; }
#endif
