#version 450
// SPDX-License-Identifier: Apache-2.0
// A dusk gradient and the sun's disc (HDR: the disc is what the sun's flare measures).
layout(location = 0) in vec2 ndc;
layout(push_constant) uniform Sky {
    vec4 right, up, forward;   // the camera's basis
    vec4 sun;                  // xyz: toward the sun; w: cos of its angular radius
    vec4 tanHalf;              // xy: tan(fov / 2) across and up
};
layout(location = 0) out vec4 fragColor;
void main() {
    vec3 d = normalize(forward.xyz + right.xyz * (ndc.x * tanHalf.x) - up.xyz * (ndc.y * tanHalf.y));
    vec3 sky = mix(vec3(0.9, 0.6, 0.4), vec3(0.15, 0.25, 0.55), clamp(d.y * 3.0, 0.0, 1.0));
    fragColor = vec4(dot(d, sun.xyz) >= sun.w ? vec3(3000.0, 2600.0, 2000.0) : sky, 1.0);
}
