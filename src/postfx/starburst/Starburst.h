// SPDX-License-Identifier: Apache-2.0
// Procedural starburst modulation of the flare, as John Chapman's pseudo lens flare modulates
// its ghosts and halo with a starburst texture: here the texture is a function of the angle
// about each of the frame's bright sources (aspect space; Chapman uses the screen centre,
// which reads as a second sun, still there as "centre": "frame"). `spokes` rays, each with a seeded
// brightness in [0.5, 1] and a profile (1 - (d / width)^2)^2 over its angular distance d (in spoke
// spacings), so neighbouring rays meet at zero and the pattern is continuous all the way round.
// modulation = max(0, 1 - intensity + 2 intensity star): 1 everywhere at intensity 0.
// The ray brightnesses come from the CPU (a uniform array in GL). Twin: shaders/starburst.glsl.
#pragma once

#include <array>
#include <numbers>

#include "core/Random.h"
#include "flarekit/PostFx.h"
#include "postfx/Kernel.h"

namespace flarekit::postfx {

struct StarburstUniforms {
    float intensity = 0.f, width = 0.15f;
    int spokes = 12;
    std::array<float, kMaxSpokes> rays{};
    int centreCount = 1;
    std::array<Vec2, kMaxStarCentres> centres{Vec2{0.5f, 0.5f}};  //!< uv
};

inline StarburstUniforms starburstUniforms(const StarburstParams& p) {
    StarburstUniforms u;
    u.intensity = p.intensity, u.width = p.width, u.spokes = std::clamp(p.spokes, 2, kMaxSpokes);
    SplitMix64 random(p.seed);
    for (float& ray : u.rays) ray = 0.5f + 0.5f * random.nextFloat();
    if (p.centre == StarCentre::Frame) return u;
    u.centreCount = std::clamp(p.centreCount, 1, kMaxStarCentres);
    for (int i = 0; i < kMaxStarCentres; ++i)
        u.centres[std::size_t(i)] = {p.centresUv[std::size_t(2 * i)],
                                     p.centresUv[std::size_t(2 * i + 1)]};
    return u;
}

inline float rayProfile(float d, float width) {
    const float t = std::max(0.f, 1.f - (d / width) * (d / width));
    return t * t;
}

//! The star about one centre c (uv): rays by angle in aspect space.
inline float starAbout(const StarburstUniforms& u, Vec2 uv, Vec2 c, float aspect) {
    const Vec2 q{(uv.x - c.x) * 2.f * aspect, (uv.y - c.y) * 2.f};
    const float angle = (q.x == 0.f && q.y == 0.f) ? 0.f : std::atan2(q.y, q.x);
    const float t = (angle * (0.5f / std::numbers::pi_v<float>)+0.5f) * float(u.spokes);
    const float k = std::floor(t), f = t - k;
    const int ray = int(k) % u.spokes, next = (int(k) + 1) % u.spokes;
    return u.rays[std::size_t(ray)] * rayProfile(f, u.width) +
           u.rays[std::size_t(next)] * rayProfile(1.f - f, u.width);
}

//! With several centres a pixel takes the strongest ray through it: every source its star.
inline float starburstModulation(const StarburstUniforms& u, Vec2 uv, float aspect) {
    if (u.intensity == 0.f) return 1.f;
    float star = 0.f;
    for (int i = 0; i < u.centreCount; ++i) {
        star = std::max(star, starAbout(u, uv, u.centres[std::size_t(i)], aspect));
    }
    return std::max(0.f, 1.f - u.intensity + 2.f * u.intensity * star);
}

}  // namespace flarekit::postfx
