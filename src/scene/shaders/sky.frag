#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Sky behind everything: a gradient by elevation and the sun disc at infinity, colour x
// intensity inside its angular radius. The view ray comes from the inverse view-projection.
uniform mat4 inverseViewProjection;
uniform vec2 viewportSize;
uniform vec3 sunDirection;
uniform vec3 sunRadiance;
uniform float cosSunRadius;
uniform vec3 horizonColor;
uniform vec3 zenithColor;
out vec4 fragColor;
void main() {
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    vec4 farPoint = inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec4 nearPoint = inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec3 ray = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    float elevation = clamp(ray.y, 0.0, 1.0);
    vec3 sky = mix(horizonColor, zenithColor, sqrt(elevation));
    if (ray.y < 0.0) sky = horizonColor * 0.5;  // below the horizon: dim ground haze
    if (dot(ray, sunDirection) >= cosSunRadius) sky = sunRadiance;
    fragColor = vec4(sky, 1.0);
}
