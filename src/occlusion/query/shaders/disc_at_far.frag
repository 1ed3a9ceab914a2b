#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The sun's disc drawn at the far plane, for occlusion queries: a pixel counts when its centre
// is inside the disc and, with the depth test on, nothing nearer than the far plane covers it.
out vec4 fragColor;
void main() {
    if (!inSunDisc(rayThrough(gl_FragCoord.xy))) discard;
    gl_FragDepth = lightDepth;  // the far plane for the sun
    fragColor = vec4(1.0);
}
