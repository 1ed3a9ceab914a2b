// SPDX-License-Identifier: Apache-2.0
#include "engine/FlareInstances.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flarekit/Flare.h"
#include "flarekit/Temporal.h"

namespace flarekit::engine {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

struct V3 {
    float x = 0, y = 0, z = 0;
};
float dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

//! light_view.glsl's LightView, the parts the flare reads.
struct LightView {
    V3 axis, centre;
    float halfAngle = 0, radius = 0;
    bool point = false, inside = false;
};

//! lightView of light_view.glsl; the view matrix is column-major like the shader's.
LightView lightView(const fk_light& l, const float* m) {
    LightView v;
    v.point = l.type == FK_LIGHT_POINT;
    v.radius = v.point ? l.radius : l.radius * (kPi / 180.f);  // packLights: radians
    if (v.point) {
        const float* p = l.position;
        v.centre = {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
                    m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
                    m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
        const float distance = std::sqrt(dot(v.centre, v.centre));
        v.inside = distance <= v.radius;
        v.axis = v.inside ? V3{0, 0, -1}
                          : V3{v.centre.x / distance, v.centre.y / distance, v.centre.z / distance};
        v.halfAngle = v.inside ? kPi : std::asin(v.radius / distance);
    } else {
        const float* d = l.direction;
        const V3 a{m[0] * d[0] + m[4] * d[1] + m[8] * d[2], m[1] * d[0] + m[5] * d[1] + m[9] * d[2],
                   m[2] * d[0] + m[6] * d[1] + m[10] * d[2]};
        const float n = std::sqrt(dot(a, a));
        v.axis = {a.x / n, a.y / n, a.z / n};
        v.halfAngle = v.radius;
    }
    return v;
}

//! projectionMatrix * (x, y, z, w), column-major.
void project(const float* p, V3 xyz, float w, float clip[4]) {
    for (int r = 0; r < 4; ++r)
        clip[r] = p[r] * xyz.x + p[4 + r] * xyz.y + p[8 + r] * xyz.z + p[12 + r] * w;
}

}  // namespace

void appendFlareInstances(const fk_frame& f, const fk_light* lights, const float* coverage,
                          int count, int presetId, std::span<const InstanceSprite> sprites,
                          float edgeFadeWidth, std::vector<fk_flare_instance>& out) {
    const float sizeX = float(f.viewport[2]), sizeY = float(f.viewport[3]);
    for (const InstanceSprite& s : sprites) {
        for (int i = 0; i < count; ++i) {
            const fk_light& l = lights[i];
            if (l.preset != presetId) continue;
            const LightView v = lightView(l, f.view);
            float clip[4];
            project(f.projection, v.point ? v.centre : v.axis, v.point ? 1.f : 0.f, clip);
            const Point light{(clip[0] / clip[3] * 0.5f + 0.5f) * sizeX,
                              (clip[1] / clip[3] * 0.5f + 0.5f) * sizeY};  // bottom-left
            const V3 radiance{l.color[0] * l.intensity, l.color[1] * l.intensity,
                              l.color[2] * l.intensity};
            const float lum = dot(radiance, {0.2126f, 0.7152f, 0.0722f});
            const float tanRadius =
                v.point
                    ? v.radius /
                          std::sqrt(std::max(1e-30f, dot(v.centre, v.centre) - v.radius * v.radius))
                    : std::tan(v.halfAngle);
            const float radiusOfHeight = tanRadius * std::abs(f.projection[5]) / 2.f;
            const float flux = lum * kPi * radiusOfHeight * radiusOfHeight / float(kReferenceFlux);
            const float weight = coverage[i];
            const EdgePlacement edge =
                s.edgeStreak ? edgeStreakPlacement(light, f.viewport[2], f.viewport[3], s.reach)
                             : EdgePlacement{{0, 0}, 0, 1};
            const float fade =
                s.edgeStreak
                    ? edge.weight
                    : float(edgeFade(light, f.viewport[2], f.viewport[3], double(edgeFadeWidth)));
            const float intensity = clip[3] > 0 && !v.inside ? weight * fade * flux : 0.f;
            if (!(intensity > 0.f) || !std::isfinite(intensity) || !(lum > 0.f)) continue;
            fk_flare_instance r{};
            const Point centre = s.edgeStreak
                                     ? edge.centre
                                     : Point{sizeX * 0.5f + s.t * (light.x - sizeX * 0.5f),
                                             sizeY * 0.5f + s.t * (light.y - sizeY * 0.5f)};
            r.position[0] = centre.x;
            r.position[1] = centre.y;
            r.half_size[0] = s.halfW;
            r.half_size[1] = s.halfH;
            r.rotation = edge.rotationDeg > 45.f ? kPi / 2.f : 0.f;  // a side edge: a quarter turn
            r.color[0] = radiance.x / lum * intensity;
            r.color[1] = radiance.y / lum * intensity;
            r.color[2] = radiance.z / lum * intensity;
            r.texture = s.slot;
            r.light = i;
            r.preset = presetId;
            r.element = s.element;
            out.push_back(r);
        }
    }
}

}  // namespace flarekit::engine
