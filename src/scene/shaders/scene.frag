#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Lambert lighting from the sun (its irradiance: radiance x the disc's solid angle, so a sun of
// 2,400 and 1.5 degrees lights surfaces to about 5) times its shadow-map visibility, plus a
// flat sky ambient.
// Triangles are double-sided: a normal facing away from the eye is flipped. (Not
// gl_FrontFacing: box and sphere windings are not kept consistent, their normals are.)
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 albedo;
uniform vec3 sunDirection;
uniform vec3 sunIrradiance;
uniform vec3 ambient;
uniform vec3 cameraPosition;
uniform bool shadowsEnabled;
uniform sampler2DShadow sunShadow;
uniform mat4 shadowMatrix;   // world -> shadow map [0, 1]^3
uniform float opacity;       // 1 for opaque objects; translucent ones are blended over
uniform float shadowTexel;   // world size of one shadow-map texel, metres
out vec4 fragColor;

// 3x3 taps of the hardware 2x2 compare: a 4-texel-wide soft edge, no acne thanks to the
// normal offset (1.5 texels along the normal, which grows with the grazing angle's slope).
float sunVisibility(vec3 p, vec3 n) {
    vec4 s = shadowMatrix * vec4(p + n * (1.5 * shadowTexel), 1.0);
    if (any(lessThan(s.xyz, vec3(0.0))) || any(greaterThan(s.xyz, vec3(1.0)))) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(sunShadow, 0));
    float lit = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) lit += texture(sunShadow, vec3(s.xy + vec2(i, j) * texel, s.z));
    return lit / 9.0;
}

void main() {
    vec3 n = normalize(worldNormal);
    if (dot(n, cameraPosition - worldPosition) < 0.0) n = -n;
    float facing = max(dot(n, sunDirection), 0.0);
    float visible = (shadowsEnabled && facing > 0.0) ? sunVisibility(worldPosition, n) : 1.0;
    vec3 light = sunIrradiance * facing * visible + ambient;
    fragColor = vec4(albedo * light, opacity);
}
