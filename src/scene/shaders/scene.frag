#version 450 core
// Lambert lighting from the sun (its colour x a tenth of its intensity, so a sun of 50
// lights surfaces to about 5) plus a flat sky ambient. Triangles are double-sided.
in vec3 worldNormal;
in vec3 albedo;
uniform vec3 sunDirection;
uniform vec3 sunRadiance;
uniform vec3 ambient;
out vec4 fragColor;
void main() {
    vec3 n = normalize(gl_FrontFacing ? worldNormal : -worldNormal);
    vec3 light = sunRadiance * 0.1 * max(dot(n, sunDirection), 0.0) + ambient;
    fragColor = vec4(albedo * light, 1.0);
}
