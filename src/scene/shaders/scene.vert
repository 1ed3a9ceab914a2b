#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Scene geometry: world-space positions, normals and colours, one draw for all objects. The
// shadow pass uses it too, with the sun's view-projection.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec3 albedo;
void main() {
    worldPosition = position;
    worldNormal = normal;
    albedo = color;
    gl_Position = viewProjection * vec4(position, 1.0);
}
