#version 450
// SPDX-License-Identifier: Apache-2.0
// VulkanOccluders: a scene's objects drawn into a sun-map tile (the Vulkan occluder callback
// of the CLI and the tests, as SceneOccluders is on GL): black, or 1 - opacity.
layout(location = 0) in vec3 position;
layout(push_constant) uniform Occluder {
    mat4 viewProjection;
    float keep;  // the share of light let through: 0 opaque
};
void main() { gl_Position = viewProjection * vec4(position, 1.0); }
