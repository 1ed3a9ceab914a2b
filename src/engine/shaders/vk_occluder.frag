#version 450
// SPDX-License-Identifier: Apache-2.0
layout(push_constant) uniform Occluder {
    mat4 viewProjection;
    float keep;
};
layout(location = 0) out vec4 fragColor;
void main() { fragColor = vec4(keep, keep, keep, 1.0); }
