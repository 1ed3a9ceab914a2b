#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Sun map -> intensity map (GPG2 step 4): one point per sample, all landing on the single
// texel of the 1x1 intensity map, where additive blending sums them.
layout(std430, binding = 1) readonly buffer Samples { vec2 samplePos[]; };
out vec2 uv;
void main() {
    uv = samplePos[gl_VertexID];
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
