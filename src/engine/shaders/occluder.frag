#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Black for an opaque occluder; 1 - opacity, multiplied into the white tile, for a
// translucent one.
uniform float keep;
out vec4 fragColor;
void main() { fragColor = vec4(vec3(keep), 1.0); }
