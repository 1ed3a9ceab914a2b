#version 450
// SPDX-License-Identifier: Apache-2.0
layout(location = 0) in vec3 n;
layout(location = 1) in vec4 c;
layout(push_constant) uniform Camera {
    mat4 viewProjection;
    vec4 sunDirection;
};
layout(location = 0) out vec4 fragColor;
void main() {
    vec3 lit = c.rgb * (6.0 * max(dot(normalize(n), sunDirection.xyz), 0.0) + vec3(0.25, 0.3, 0.4));
    fragColor = vec4(c.a > 0.5 ? c.rgb : lit, 1.0);
}
