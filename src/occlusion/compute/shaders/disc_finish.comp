#version 450 core
// SPDX-License-Identifier: Apache-2.0
// `compute`, pass 2: one work group adds up the partial sums and writes visible / total into
// the 1x1 coverage image in place; nothing leaves the GPU.
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer Partials { vec2 partial[]; };
layout(r32f, binding = 0) uniform writeonly image2D coverage;
uniform int partialCount;
shared vec2 sums[256];

void main() {
    uint index = gl_LocalInvocationIndex;
    vec2 s = vec2(0.0);
    for (int i = int(index); i < partialCount; i += 256) s += partial[i];
    sums[index] = s;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (index < stride) sums[index] += sums[index + stride];
        barrier();
    }
    if (index == 0u) imageStore(coverage, ivec2(0), vec4(sums[0].y > 0.0 ? sums[0].x / sums[0].y : 0.0));
}
