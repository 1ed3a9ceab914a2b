// SPDX-License-Identifier: Apache-2.0
// The example's own world: a grid of city blocks with street lamps on every pavement and a low
// sun, as plain boxes and sphere lights, plus the camera that looks down one street. It can
// write itself as a flarekit Scene JSON so `flarekit visibility --method raycast` can judge
// what the engine measured.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

struct V3 {
    float x = 0, y = 0, z = 0;
};
struct CityBox {
    V3 lo, hi, color;
};
//! A lamp's glass bulb is drawn (opaque, into depth) at this share of its light's radius, and
//! written into the Scene JSON as a sphere of that size: nearer bulbs hide farther lamps.
inline constexpr float kBulbShare = 0.96f;

struct Lamp {
    V3 position;
    float radius;
};
struct City {
    std::vector<CityBox> boxes;
    std::vector<Lamp> lamps;
    V3 sunDirection{0.02f, 0.13f, -1.f};  // low, over the far end of the street
    float sunRadiusDeg = 0.53f;
    V3 eye{21.f, 1.7f, 70.f}, target{19.f, 6.f, -200.f};
    float fovYDeg = 55.f, nearPlane = 0.1f, farPlane = 2000.f;
};

//! Blocks 30 m square on a 42 m grid (12 m streets), heights 8-48 m from a hash; lamps 4.35 m
//! up every 14 m along both pavements of the streets near the camera, each on a thin post.
inline City makeCity() {
    City c;
    unsigned state = 12345u;
    const auto next = [&](float lo, float hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * float(state >> 8) / float(1u << 24);
    };
    for (int i = -3; i <= 3; ++i)
        for (int j = -4; j <= 1; ++j) {
            const float cx = 42.f * float(i), cz = 42.f * float(j), h = next(8, 48);
            c.boxes.push_back({{cx - 15, 0, cz - 15}, {cx + 15, h, cz + 15}, {0.45f, 0.42f, 0.4f}});
        }
    const auto lampAt = [&](float x, float z, float radius = 0.3f) {
        c.boxes.push_back({{x - 0.07f, 0, z - 0.07f},
                           {x + 0.07f, 4.05f - radius, z + 0.07f},
                           {0.2f, 0.2f, 0.22f}});
        c.lamps.push_back({{x, 4.35f, z}, radius});
    };
    // Two big globes in the first side street, just around the corners of the blocks on either
    // side: from the camera, each sits half behind a building's edge.
    lampAt(14.5f, -22.1f, 0.5f);
    lampAt(27.5f, -22.1f, 0.5f);
    for (int street = -1; street <= 1; ++street) {  // along z, at x = 21 + 42k
        const float x = 21.f + 42.f * float(street);
        for (float z = 60.f; z > -180.f; z -= 14.f) lampAt(x - 5.2f, z), lampAt(x + 5.2f, z - 7.f);
    }
    for (int street = -4; street <= 1; ++street) {  // along x, at z = 21 + 42k
        const float z = 21.f + 42.f * float(street);
        for (float x = -110.f; x < 110.f; x += 14.f) {
            if (std::fmod(std::fabs(x - 21.f), 42.f) < 8.f) continue;  // leave the crossings free
            lampAt(x, z - 5.2f), lampAt(x + 7.f, z + 5.2f);
        }
    }
    return c;
}

//! The world as Scene JSON (docs/scenes.md): boxes, the ground, the lamps and the sun.
inline bool writeSceneJson(const City& c, int width, int height, const std::string& path) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) return false;
    std::fprintf(f, "{\"image\": {\"width\": %d, \"height\": %d},\n", width, height);
    std::fprintf(f,
                 " \"camera\": {\"position\": [%g, %g, %g], \"look_at\": [%g, %g, %g], "
                 "\"fov_y_deg\": %g, \"near\": %g, \"far\": %g},\n",
                 c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.fovYDeg,
                 c.nearPlane, c.farPlane);
    std::fprintf(f, " \"ground\": {\"height\": 0},\n \"lights\": [\n");
    std::fprintf(f,
                 "  {\"type\": \"directional\", \"direction\": [%g, %g, %g], "
                 "\"angular_radius_deg\": %g, \"color\": [1, 0.87, 0.67], \"intensity\": 3000, "
                 "\"preset\": \"tanczos-classic\"}",
                 c.sunDirection.x, c.sunDirection.y, c.sunDirection.z, c.sunRadiusDeg);
    for (const Lamp& l : c.lamps)
        std::fprintf(f,
                     ",\n  {\"type\": \"point\", \"position\": [%g, %g, %g], \"radius\": %g, "
                     "\"color\": [1, 0.75, 0.45], \"intensity\": 2500, \"preset\": \"subtle\"}",
                     l.position.x, l.position.y, l.position.z, l.radius);
    std::fprintf(f, "],\n \"objects\": [\n");
    for (std::size_t i = 0; i < c.boxes.size(); ++i) {
        const CityBox& b = c.boxes[i];
        std::fprintf(f, "%s  {\"type\": \"box\", \"min\": [%g, %g, %g], \"max\": [%g, %g, %g]}",
                     i ? ",\n" : "", b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z);
    }
    for (const Lamp& l : c.lamps)
        std::fprintf(f, ",\n  {\"type\": \"sphere\", \"center\": [%g, %g, %g], \"radius\": %g}",
                     l.position.x, l.position.y, l.position.z, l.radius * kBulbShare);
    std::fprintf(f, "\n ]}\n");
    return std::fclose(f) == 0;
}
