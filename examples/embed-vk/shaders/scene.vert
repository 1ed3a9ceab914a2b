#version 450
// SPDX-License-Identifier: Apache-2.0
// embed-vk's city: boxes lit by the sun, lamp bulbs emissive (colour alpha 1).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(push_constant) uniform Camera {
    mat4 viewProjection;
    vec4 sunDirection;
};
layout(location = 0) out vec3 n;
layout(location = 1) out vec4 c;
void main() {
    n = normal;
    c = color;
    gl_Position = viewProjection * vec4(position, 1.0);
}
