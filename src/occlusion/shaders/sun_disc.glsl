// SPDX-License-Identifier: Apache-2.0
// The sun's projected disc, shared by every GPU visibility method (prepended to their shaders
// after #version). Reads the same, line for line, as src/occlusion/SunDisc.cpp.
uniform vec3 camRight, camUp, camForward;  // gluLookAt basis
uniform vec2 tanHalfFov;                   // tan(fov / 2) horizontally, vertically
uniform vec2 frameSize;                    // pixels
uniform vec3 sunDir;                       // unit, toward the sun
uniform float sunChord2;                   // |d - s|^2 at the rim: 2 (1 - cos(radius))
uniform float lightDepth;  // the light's stored depth: 1 (sky) for the sun, a sphere light's near side

// The unit view ray through a point of the frame in GL pixel units (origin bottom-left).
vec3 rayThrough(vec2 p) {
    vec2 ndc = p / frameSize * 2.0 - 1.0;
    return normalize(camForward + camRight * (ndc.x * tanHalfFov.x) + camUp * (ndc.y * tanHalfFov.y));
}

// Inside the disc: the chord test |d - s|^2 <= 2 (1 - cos r) keeps float precision for small
// suns, where 1 - dot(d, s) would cancel.
bool inSunDisc(vec3 d) {
    vec3 e = d - sunDir;
    return dot(e, e) <= sunChord2;
}

// Weight of GL pixel (x, y): the share of its area inside the disc (4 x 4 sub-samples) times
// cos^3 of its centre's angle to the axis, the solid angle a pixel spans relative to the axis
// pixel, so sums over pixels are uniform over solid angle like the ray-cast truth.
float discWeight(vec2 pixel) {
    int inside = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            if (inSunDisc(rayThrough(pixel + (vec2(i, j) + 0.5) / 4.0))) ++inside;
    float cosTheta = dot(rayThrough(pixel + 0.5), camForward);
    return float(inside) / 16.0 * cosTheta * cosTheta * cosTheta;
}
