// SPDX-License-Identifier: Apache-2.0
// The city as a triangle mesh, its lights as flarekit sees them, and the camera maths both
// embedding examples (embed-gl, embed-vk) share: each application still owns its renderer;
// only the world and its matrices are common, so the two draw the same frame.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "City.h"
#include "flarekit/flarekit.h"

using Mat = std::array<float, 16>;  // column-major

inline Mat lookAt(V3 eye, V3 target) {
    V3 f{target.x - eye.x, target.y - eye.y, target.z - eye.z};
    const float fl = std::sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
    f = {f.x / fl, f.y / fl, f.z / fl};
    V3 s{-f.z, 0.f, f.x};  // f x up, up = +y
    const float sl = std::sqrt(s.x * s.x + s.z * s.z);
    s = {s.x / sl, 0.f, s.z / sl};
    const V3 u{s.y * f.z - s.z * f.y, s.z * f.x - s.x * f.z, s.x * f.y - s.y * f.x};
    const float ts = s.x * eye.x + s.y * eye.y + s.z * eye.z,
                tu = u.x * eye.x + u.y * eye.y + u.z * eye.z,
                tf = f.x * eye.x + f.y * eye.y + f.z * eye.z;
    // A column a line.
    // clang-format off
    return {s.x, u.x, -f.x, 0,
            s.y, u.y, -f.y, 0,
            s.z, u.z, -f.z, 0,
            -ts, -tu,  tf,  1};
    // clang-format on
}

inline Mat multiply(const Mat& a, const Mat& b) {
    Mat r{};
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
    return r;
}

struct Vertex {
    float p[3], n[3], c[4];
};

inline void pushBox(std::vector<Vertex>& out, const CityBox& b) {
    const float lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const float uv[4][2] = {{lo[u], lo[v]}, {hi[u], lo[v]}, {hi[u], hi[v]}, {lo[u], hi[v]}};
            for (int k : {0, 1, 2, 0, 2, 3}) {
                Vertex x{};
                x.p[axis] = side ? hi[axis] : lo[axis];
                x.p[u] = uv[k][0], x.p[v] = uv[k][1];
                x.n[axis] = side ? 1.f : -1.f;
                x.c[0] = b.color.x, x.c[1] = b.color.y, x.c[2] = b.color.z;
                out.push_back(x);
            }
        }
}

//! A lamp's bulb: a 12 x 8 sphere of kBulbShare of the light's radius, its vertices on that
//! sphere (so the whole bulb lies inside the light: the engine's test at the light sphere's
//! near side sees the bulb as part of the light, not in front of it).
inline void pushBulb(std::vector<Vertex>& out, const Lamp& l) {
    const float r = l.radius * kBulbShare, pi = 3.14159265f;
    const auto at = [&](int slice, int stack) {
        const float theta = pi * float(stack) / 8.f, phi = 2.f * pi * float(slice) / 12.f;
        Vertex x{};
        const float d[3] = {std::sin(theta) * std::cos(phi), std::cos(theta),
                            std::sin(theta) * std::sin(phi)};
        x.p[0] = l.position.x + r * d[0], x.p[1] = l.position.y + r * d[1],
        x.p[2] = l.position.z + r * d[2];
        x.n[0] = d[0], x.n[1] = d[1], x.n[2] = d[2];
        x.c[0] = 2500.f, x.c[1] = 1875.f, x.c[2] = 1125.f, x.c[3] = 1.f;
        return x;
    };
    for (int st = 0; st < 8; ++st)
        for (int sl = 0; sl < 12; ++sl) {
            const Vertex a = at(sl, st), b = at(sl + 1, st), c = at(sl + 1, st + 1),
                         d = at(sl, st + 1);
            for (const Vertex& v : {a, b, c, a, c, d}) out.push_back(v);
        }
}

//! The unit vector toward the sun.
inline V3 sunToward(const City& city) {
    const V3& d = city.sunDirection;
    const float l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return {d.x / l, d.y / l, d.z / l};
}

//! The sun, then every lamp, as flarekit lights with these presets.
inline std::vector<fk_light> cityLights(const City& city, int sunPreset, int lampPreset) {
    const V3 sun = sunToward(city);
    std::vector<fk_light> lights;
    fk_light s{};
    s.type = FK_LIGHT_DIRECTIONAL;
    s.direction[0] = sun.x, s.direction[1] = sun.y, s.direction[2] = sun.z;
    s.radius = city.sunRadiusDeg;
    s.color[0] = 1.f, s.color[1] = 0.87f, s.color[2] = 0.67f;
    s.intensity = 3000.f;
    s.preset = sunPreset;
    lights.push_back(s);
    for (const Lamp& l : city.lamps) {
        fk_light p{};
        p.type = FK_LIGHT_POINT;
        p.position[0] = l.position.x, p.position[1] = l.position.y, p.position[2] = l.position.z;
        p.radius = l.radius;
        p.color[0] = 1.f, p.color[1] = 0.75f, p.color[2] = 0.45f;
        p.intensity = 2500.f;  // sodium-bright against the dusk: flares a fifth of the sun's
        p.preset = lampPreset;
        lights.push_back(p);
    }
    return lights;
}
