#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The scene's occluders seen from a light's sun-map camera (the texture-mask occluder callback
// of flarekit lights and visibility): positions only.
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;
void main() { gl_Position = viewProjection * vec4(position, 1.0); }
