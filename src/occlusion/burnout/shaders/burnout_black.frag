#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Burnout chain, pass 2: the black rectangle at the far plane, depth-tested (LEQUAL): it lands
// only on sub-cells where the frame shows sky, so R = 0 exactly where the sun is visible.
uniform float lightDepth;  // 1 (the far plane) for the sun; a sphere light's near side
out vec4 fragColor;
void main() {
    gl_FragDepth = lightDepth;  // the far plane for the sun
    fragColor = vec4(0.0);
}
