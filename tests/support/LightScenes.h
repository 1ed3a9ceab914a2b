// SPDX-License-Identifier: Apache-2.0
// Generated many-light scenes for the engine API: sphere lights among boxes and spheres, some
// of them partly hidden, with translucent cards (opacity 0.3-0.7) between the camera and every
// light. Lights sit inside the frame with a margin, so the screen-space measurement and the
// ray-cast truth speak of the same cone. Deterministic for a seed.
#pragma once

#include <cmath>
#include <numbers>

#include "flarekit/Scene.h"
#include "scene/CameraMath.h"

namespace flarekit::test {

inline double lampUniform(unsigned& state) {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
}

//! Lights' radii on screen, in pixels, drawn log-uniformly from [min, max]; {0, 0} keeps
//! the world radii of 0.15-0.5 m.
struct PixelRadii {
    double min = 0, max = 0;
};

inline Scene lampScene(int lights, unsigned seed, bool translucent = true, int width = 1280,
                       int height = 720, PixelRadii pixelRadii = {}) {
    Scene s;
    s.width = width;
    s.height = height;
    s.camera.position = {0, 1.7, 0};
    s.camera.lookAt = {0, 1.7, -20};
    s.camera.fovYDeg = 50;
    s.sun.intensity = 0;
    unsigned r = seed * 2654435761u + 1u;
    const auto u = [&](double lo, double hi) { return lo + (hi - lo) * lampUniform(r); };
    for (int i = 0; i < 40; ++i) {  // posts and blocks, 6-60 m ahead
        const Vec3 c{u(-25, 25), u(-2, 6), -u(6, 60)};
        const Vec3 half{u(0.1, 1.5), u(0.3, 4), u(0.1, 1.5)};
        s.boxes.push_back({c - half, c + half, {0.4, 0.4, 0.45}});
    }
    for (int i = 0; i < 30; ++i)
        s.spheres.push_back({{u(-25, 25), u(-2, 8), -u(6, 60)}, u(0.2, 1.5), {0.2, 0.4, 0.2}});
    if (translucent) {  // glass and fog cards 2.5-4 m ahead, in front of every light
        for (int i = 0; i < 4; ++i) {
            const Vec3 c{u(-1.5, 1.5), 1.7 + u(-0.8, 0.8), -u(2.5, 4)};
            const Vec3 half{u(0.3, 0.8), u(0.2, 0.6), 0.02};
            s.boxes.push_back({c - half, c + half, {0.7, 0.8, 0.9}, u(0.3, 0.7)});
        }
    }
    while (int(s.lights.size()) < lights) {
        SceneLight l;
        l.type = LightType::Point;
        l.position = {u(-20, 20), u(-1, 7), -u(8, 55)};
        l.radius = u(0.15, 0.5);
        if (pixelRadii.max > 0) {  // r px = radius / distance x focal length in pixels
            const double px = pixelRadii.min * std::pow(pixelRadii.max / pixelRadii.min, u(0, 1));
            const double focal =
                0.5 * height / std::tan(s.camera.fovYDeg * std::numbers::pi / 360.0);
            l.radius = px * length(l.position - s.camera.position) / focal;
        }
        l.color = {1.0, u(0.6, 0.9), u(0.3, 0.6)};
        l.intensity = u(20, 80);
        l.preset = "subtle";
        Point p;
        const double margin = 0.06 * height;
        if (!projectPoint(s, l.position, p) || p.x < margin || p.x > width - margin ||
            p.y < margin || p.y > height - margin)
            continue;
        // Not inside an opaque object: the ray caster and a depth buffer disagree there.
        bool inside = false;
        for (const Box& b : s.boxes) {
            const Vec3& q = l.position;
            inside |= q.x > b.min.x - l.radius && q.x < b.max.x + l.radius &&
                      q.y > b.min.y - l.radius && q.y < b.max.y + l.radius &&
                      q.z > b.min.z - l.radius && q.z < b.max.z + l.radius;
        }
        for (const Sphere& sp : s.spheres)
            inside |= length(l.position - sp.center) < sp.radius + l.radius;
        if (!inside) s.lights.push_back(l);
    }
    return s;
}

}  // namespace flarekit::test
