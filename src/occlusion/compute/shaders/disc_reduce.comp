#version 450 core
// SPDX-License-Identifier: Apache-2.0
// `compute`, pass 1: each 16x16 work group sums, over its pixels of the disc's box, the disc
// weight of sky pixels (depth at the cleared 1.0) and of all pixels, by a shared-memory tree
// reduction, and writes the pair to its slot of the partial sums. Built twice: with MULTISAMPLE
// defined it reads every MSAA depth sample, and a pixel counts by the share of its samples that
// see sky, which resolves occluders thinner than a pixel.
layout(local_size_x = 16, local_size_y = 16) in;
#ifdef MULTISAMPLE
layout(binding = 0) uniform sampler2DMS sceneDepth;
uniform int sampleCount;
#else
layout(binding = 0) uniform sampler2D sceneDepth;
#endif
uniform ivec2 boxOrigin;
uniform ivec2 boxSize;
layout(std430, binding = 0) writeonly buffer Partials { vec2 partial[]; };
shared vec2 sums[256];

void main() {
    uint index = gl_LocalInvocationIndex;
    vec2 s = vec2(0.0);
    if (all(lessThan(gl_GlobalInvocationID.xy, uvec2(boxSize)))) {
        ivec2 pixel = boxOrigin + ivec2(gl_GlobalInvocationID.xy);
        float weight = discWeight(vec2(pixel));
#ifdef MULTISAMPLE
        int sky = 0;
        for (int i = 0; i < sampleCount; ++i) sky += texelFetch(sceneDepth, pixel, i).r >= lightDepth ? 1 : 0;
        s = vec2(weight * float(sky) / float(sampleCount), weight);
#else
        float depth = texelFetch(sceneDepth, pixel, 0).r;
        s = vec2(depth >= lightDepth ? weight : 0.0, weight);
#endif
    }
    sums[index] = s;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (index < stride) sums[index] += sums[index + stride];
        barrier();
    }
    if (index == 0u) partial[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = sums[0];
}
