// SPDX-License-Identifier: Apache-2.0
// A light of the engine API as the camera sees it, in view space: its cone of directions
// (axis and half-angle) and where a direction of that cone lands in the depth texture, with
// the light's own stored depth there. Prepended to light_coverage.comp and light_flare.vert.
// The cone and its sampling read as src/occlusion/SunCone.h and the ray caster do.
struct Light {
    vec4 positionType;     // xyz: world position (point); w: 0 directional, 1 point
    vec4 directionRadius;  // xyz: toward the light (directional); w: radius (world units or radians)
    vec4 colorIntensity;   // rgb: colour; a: intensity
    vec4 presetPad;        // x: preset id (-1: no flare)
};
layout(std430, BINDING(6, 1)) readonly buffer Lights { Light lights[]; };

UNIFORMS_BEGIN(ViewParams, 0)
UNIFORM mat4 viewMatrix;        // world to view, rigid
UNIFORM mat4 projectionMatrix;  // view to clip
UNIFORM ivec4 viewport;         // x, y, w, h in the depth texture (or framebuffer)
UNIFORM vec2 depthTextureSize;
UNIFORM int depthConvention;    // fk_depth_convention
UNIFORM bool depthPastViewport;  // fk_engine_set_guard_band
UNIFORMS_END

const float kPi = 3.14159265358979;
// A point light is tested at its sphere's near side pulled 0.1% toward the camera, so a bulb
// mesh the application draws at the light's sphere does not hide its own light.
const float kNearSide = 0.999;

struct LightView {
    vec3 axis;        // unit, view space, toward the light
    float halfAngle;  // radians
    vec3 centre;      // point light: view-space centre
    float radius;
    bool point;
    bool inside;      // the camera is inside a sphere light: it sees all of it
};

LightView lightView(Light l) {
    LightView v;
    v.point = l.positionType.w > 0.5;
    v.inside = false;
    v.centre = vec3(0.0);
    v.radius = l.directionRadius.w;
    if (v.point) {
        v.centre = (viewMatrix * vec4(l.positionType.xyz, 1.0)).xyz;
        float distance = length(v.centre);
        v.inside = distance <= v.radius;
        v.axis = v.inside ? vec3(0.0, 0.0, -1.0) : v.centre / distance;
        v.halfAngle = v.inside ? kPi : asin(v.radius / distance);
    } else {
        v.axis = normalize(mat3(viewMatrix) * l.directionRadius.xyz);
        v.halfAngle = v.radius;
    }
    return v;
}

// (a, b) in [-1, 1]^2 to a direction of the cone, uniform over solid angle: Shirley and
// Chiu's concentric map (1997) to the disc, then 1 - cos(theta) = rho^2 (1 - cos(halfAngle)),
// with 1 - cos written 2 sin^2(x / 2) to keep float precision for small lights.
vec3 coneDirection(LightView v, vec3 t1, vec3 t2, vec2 ab) {
    float rho = 0.0, phi = 0.0;
    if (ab.x == 0.0 && ab.y == 0.0) {
        rho = 0.0;
    } else if (abs(ab.x) > abs(ab.y)) {
        rho = ab.x;
        phi = (kPi / 4.0) * (ab.y / ab.x);
    } else {
        rho = ab.y;
        phi = kPi / 2.0 - (kPi / 4.0) * (ab.x / ab.y);
    }
    float s = sin(0.5 * v.halfAngle);
    float oneMinusCosTheta = rho * rho * 2.0 * s * s;
    float cosTheta = 1.0 - oneMinusCosTheta;
    float sinTheta = sqrt(max(0.0, oneMinusCosTheta * (2.0 - oneMinusCosTheta)));
    float sign = rho < 0.0 ? -1.0 : 1.0;
    return cosTheta * v.axis + (sign * sinTheta) * (cos(phi) * t1 + sin(phi) * t2);
}

// Stored depth for a normalised device z under the frame's convention, in [0, 1].
float storedDepth(float zNdc) {
    return clamp(depthConvention == 0 ? zNdc * 0.5 + 0.5 : zNdc, 0.0, 1.0);
}

// Where view-space direction d of the light lands: the depth texture's pixel (GL units), the
// light's stored depth along it, and whether that is inside the viewport. False when it falls
// behind the camera, or outside what may be read: the viewport, or with a guard band (depth
// rendered past the viewport with the same projection) the whole depth texture.
bool landsAt(LightView v, vec3 d, out vec2 pixel, out float lightDepth, out bool inView) {
    vec4 clip;
    if (v.point) {
        float b = dot(v.centre, d), c = dot(v.centre, v.centre) - v.radius * v.radius;
        float t = b - sqrt(max(0.0, b * b - c));  // rim rays graze the sphere
        clip = projectionMatrix * vec4(d * (t * kNearSide), 1.0);
    } else {
        clip = projectionMatrix * vec4(d, 0.0);  // the point at infinity
    }
    pixel = vec2(0.0);
    lightDepth = 0.0;
    inView = false;
    if (clip.w <= 0.0) return false;
    vec3 ndc = clip.xyz / clip.w;
    inView = all(lessThanEqual(abs(ndc.xy), vec2(1.0)));
    pixel = vec2(viewport.xy) + (ndc.xy * 0.5 + 0.5) * vec2(viewport.zw);
    lightDepth = storedDepth(ndc.z);
    bool inTexture = all(greaterThanEqual(pixel, vec2(0.0))) && all(lessThan(pixel, depthTextureSize));
    return depthPastViewport ? inTexture : inView;
}
