#version 450
// SPDX-License-Identifier: Apache-2.0
// One triangle over the whole target; ndc y runs down, as Vulkan's does.
layout(location = 0) out vec2 ndc;
void main() {
    ndc = vec2(gl_VertexIndex == 1 ? 3.0 : -1.0, gl_VertexIndex == 2 ? 3.0 : -1.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
}
