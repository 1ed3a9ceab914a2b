#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Sun map, step 2: occluders in black over the sun (colour mask: red only).
out vec4 fragColor;
void main() { fragColor = vec4(0.0); }
