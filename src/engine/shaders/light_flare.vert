#version 450 core
// SPDX-License-Identifier: Apache-2.0
// One flare element of one preset, instanced over every light (gl_InstanceID): a quad on the
// light's flare vector (flareVectorPoint: through the viewport's centre), collapsed for
// lights of another preset, behind the camera or with no weight. Its brightness is the
// light's filtered coverage (read here from the coverage texture, never by the CPU) x its
// edge fade (edgeFade of flarekit/Temporal.h; off where the weight has it already, as the
// temporal filter's does) x its flux in frame heights squared over
// kReferenceFlux (sunFlareScale's model: luminance x pi x (tan(angular radius) / (2 tan(fov_y
// / 2)))^2), tinted by the light's colour at unit luminance.
layout(BINDING(13, 7)) uniform sampler2D coverageTexture;
UNIFORMS_BEGIN(FlareParams, 12)
UNIFORM int coverageChannel;  // the channel of texel (light, view) that weighs the light
UNIFORM bool fadeAtEdges;     // apply edgeFade here (the weight is a raw measurement)
UNIFORM int viewIndex;
UNIFORM float guardBand;  // edge-fade width, shorter sides of the viewport
UNIFORM float referenceFlux;
UNIFORMS_END
UNIFORMS_BEGIN(ElementParams, 13)  // one element of one preset
UNIFORM vec2 halfSize;  // quad half size, pixels
UNIFORM int presetId;
UNIFORM float t;        // position on the flare vector
UNIFORM bool edgeStreak;  // this element is an edge streak (placed on the frame edge)
UNIFORM float reach;      // its reach, viewport heights
UNIFORMS_END
layout(location = 0) out vec2 uv;
layout(location = 1) flat out vec3 tint;

// edgeStreakPlacement of flarekit/Flare.h (src/flare/FlareRenderer.cpp), line for line:
// xy centre, z 1 on a side edge (turned a quarter), w the weight.
vec4 edgeStreakPlacement(vec2 light, vec2 size, float reachHeights) {
    float toLeft = light.x, toRight = size.x - light.x, toTop = light.y, toBottom = size.y - light.y;
    bool inside = min(min(toLeft, toRight), min(toTop, toBottom)) >= 0.0;
    float distance = 0.0;
    vec2 centre;
    float side;
    if (inside) {
        float nearest = min(min(toLeft, toRight), min(toTop, toBottom));
        distance = nearest;
        bool onSide = nearest == toLeft || nearest == toRight;
        side = onSide ? 1.0 : 0.0;
        centre = onSide ? vec2(nearest == toLeft ? 0.0 : size.x, light.y)
                        : vec2(light.x, nearest == toTop ? 0.0 : size.y);
    } else {
        centre = clamp(light, vec2(0.0), size);
        vec2 d = light - centre;
        distance = length(d);
        side = abs(d.x) > abs(d.y) ? 1.0 : 0.0;
    }
    float band = reachHeights * size.y;
    float u = band > 0.0 ? clamp(distance / band, 0.0, 1.0) : 1.0;
    return vec4(centre, side, 1.0 - u * u * (3.0 - 2.0 * u));
}

float edgeFade(vec2 p, vec2 size) {
    float inside = min(min(p.x, size.x - p.x), min(p.y, size.y - p.y));
    if (inside <= 0.0) return 0.0;
    float band = guardBand * min(size.x, size.y);
    return band <= 0.0 ? 1.0 : smoothstep(0.0, 1.0, inside / band);
}

void main() {
    Light l = lights[INSTANCE_ID];
    LightView v = lightView(l);
    vec4 clip = projectionMatrix * (v.point ? vec4(v.centre, 1.0) : vec4(v.axis, 0.0));
    vec2 size = vec2(viewport.zw);
    vec2 light = (clip.xy / clip.w * 0.5 + 0.5) * size;  // viewport pixels, bottom-left
    vec3 radiance = l.colorIntensity.rgb * l.colorIntensity.a;
    float lum = dot(radiance, vec3(0.2126, 0.7152, 0.0722));
    float tanRadius = v.point ? v.radius / sqrt(max(1e-30, dot(v.centre, v.centre) - v.radius * v.radius))
                              : tan(v.halfAngle);
    float radiusOfHeight = tanRadius * abs(projectionMatrix[1][1]) / 2.0;
    float flux = lum * kPi * radiusOfHeight * radiusOfHeight / referenceFlux;
    float weight = texelFetch(coverageTexture, ivec2(INSTANCE_ID, viewIndex), 0)[coverageChannel];
    vec4 edge = edgeStreak ? edgeStreakPlacement(light, size, reach) : vec4(0.0, 0.0, 0.0, 1.0);
    // An edge streak takes the coverage alone: it is what is left of the flare past the edge.
    float fade = edgeStreak ? edge.w : fadeAtEdges ? edgeFade(light, size) : 1.0;
    float intensity = clip.w > 0.0 && !v.inside ? weight * fade * flux : 0.0;
    tint = lum > 0.0 ? radiance / lum * intensity : vec3(0.0);
    bool drawn = int(l.presetPad.x) == presetId && intensity > 0.0 && !isinf(intensity) &&
                 !isnan(intensity);
    vec2 corner = vec2(VERTEX_ID & 1, (VERTEX_ID >> 1) & 1);
    // Element images are stored top row first; the quad's top is corner.y 1 (GL) or 0 (Vulkan).
    uv = vec2(corner.x, SPRITE_ROW_FROM_TOP == 1 ? corner.y : 1.0 - corner.y);
    bool transposed = edge.z > 0.5;       // a quarter turn of a doubly symmetric sprite
    if (transposed) uv = vec2(corner.y, SPRITE_ROW_FROM_TOP == 1 ? corner.x : 1.0 - corner.x);
    vec2 centre = edgeStreak ? edge.xy : size * 0.5 + t * (light - size * 0.5);
    vec2 p = centre + (corner * 2.0 - 1.0) * (transposed ? halfSize.yx : halfSize);
    gl_Position = drawn ? vec4(p / size * 2.0 - 1.0, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
