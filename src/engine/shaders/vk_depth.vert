#version 450
// SPDX-License-Identifier: Apache-2.0
// VulkanHost's depth pass: a scene's triangles with the application's view-projection (the
// CLI's and the tests' stand-in for an application's own depth pre-pass). No fragment stage.
layout(location = 0) in vec3 position;
layout(push_constant) uniform Camera { mat4 viewProjection; };
void main() { gl_Position = viewProjection * vec4(position, 1.0); }
