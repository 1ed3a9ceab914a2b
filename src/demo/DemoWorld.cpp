// SPDX-License-Identifier: Apache-2.0
// The demo world, laid out around where the sun's ray meets the roadside. The sun direction
// (0.30, 0.13, -1) climbs 0.13 m and drifts 0.30 m right per metre ahead, so from the driver
// (1.4 m up, on the centre line) it crosses the right-hand verge (x = 8-14 m) 27-47 m ahead at
// 5-7.5 m height: tree crowns there flicker it, buildings there hide it, and a 7 m tunnel
// portal hides it once the car is within ~43 m.
//
// Timeline (distance s of 231 m): narrow buildings with gaps (s 0-25), tree crowns (25-70),
// lamp posts, the tunnel (hidden, 81-123), the exit and a clear straight where exposure adapts
// to the sun, trees on the turn's verge (flicker again, 148-165), then an 80-degree left turn
// that swings the sun out of the right edge.
#include "demo/DemoWorld.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Random.h"

namespace flarekit::demo {

namespace {

constexpr double kPi = std::numbers::pi;
//! Road geometry: 175 m straight along -z, then a left arc of radius 40 m through 80 degrees.
constexpr double kStraight = 175, kTurnRadius = 40, kTurnDeg = 80;
constexpr double kTurnLength = kTurnRadius * kTurnDeg * kPi / 180;
constexpr double kDriveLength = kStraight + kTurnLength;  // 230.85 m
constexpr double kEyeHeight = 1.4;                        // a driver's eye, metres
//! Tunnel: portal face at z = -120, exit at z = -140; 10 m wide, 6 m high inside, 6.5 m
//! outside. The sun clears the portal while the car is more than (6.5 - 1.4) / 0.13 = 39 m
//! away and comes back 5 / 0.3 = 17 m before the exit: hidden for s in [81, 123] m (1.5 s).
constexpr double kTunnelStart = 120, kTunnelEnd = 140, kPortalHeight = 6.5;

// Linear albedos (no seed prescribes them; chosen to read well under the ACES curve).
constexpr Vec3 kGrass{0.10, 0.18, 0.06}, kAsphalt{0.05, 0.05, 0.055}, kPaint{0.7, 0.7, 0.65};
constexpr Vec3 kBark{0.12, 0.07, 0.04}, kConcrete{0.35, 0.34, 0.32}, kPole{0.2, 0.2, 0.22};

struct Pose {
    Vec3 position, heading;
};

Pose poseAt(double s) {
    if (s <= kStraight) return {{0, 0, -s}, {0, 0, -1}};
    const double a = (s - kStraight) / kTurnRadius;  // radians turned left
    const Vec3 centre{-kTurnRadius, 0, -kStraight};
    return {centre + Vec3{kTurnRadius * std::cos(a), 0, -kTurnRadius * std::sin(a)},
            {-std::sin(a), 0, -std::cos(a)}};
}

void addQuad(Scene& s, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 color) {
    s.triangles.push_back({a, b, c, color});
    s.triangles.push_back({a, c, d, color});
}

double uniform(SplitMix64& rng, double lo, double hi) {
    return lo + (hi - lo) * double(rng.nextFloat());
}

//! A leafy tree: a trunk box and a crown of `leaves` random leaf triangles inside an ellipsoid,
//! sparse enough that the sun flickers through the gaps.
void addLeafTree(Scene& s, SplitMix64& rng, Vec3 base, double height, int leaves) {
    s.boxes.push_back({base + Vec3{-0.2, 0, -0.2}, base + Vec3{0.2, height * 0.6, 0.2}, kBark});
    const Vec3 crown = base + Vec3{0, height * 0.65, 0};
    const double rx = height * 0.32, ry = height * 0.38;
    for (int i = 0; i < leaves; ++i) {
        Vec3 p;
        do {
            p = {uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        } while (dot(p, p) > 1);
        const Vec3 c = crown + Vec3{p.x * rx, p.y * ry, p.z * rx};
        const double size = uniform(rng, 0.35, 0.6);
        auto jitter = [&] {
            return Vec3{uniform(rng, -size, size), uniform(rng, -size, size),
                        uniform(rng, -size, size)};
        };
        const Vec3 green{uniform(rng, 0.03, 0.07), uniform(rng, 0.10, 0.20),
                         uniform(rng, 0.02, 0.05)};
        s.triangles.push_back({c + jitter(), c + jitter(), c + jitter(), green});
    }
}

//! A round tree: a trunk and two overlapping sphere crowns (the sphere foliage).
void addRoundTree(Scene& s, Vec3 base, double height) {
    s.boxes.push_back(
        {base + Vec3{-0.25, 0, -0.25}, base + Vec3{0.25, height * 0.55, 0.25}, kBark});
    const double r = height * 0.22;
    s.spheres.push_back({base + Vec3{0, height * 0.62, 0}, r, {0.05, 0.16, 0.04}});
    s.spheres.push_back(
        {base + Vec3{0.4 * r, height * 0.62 + 1.1 * r, -0.3 * r}, 0.8 * r, {0.06, 0.18, 0.05}});
}

void addRoad(Scene& s) {
    s.boxes.push_back({{-400, -1, -600}, {400, 0, 200}, kGrass});
    s.boxes.push_back({{-4, 0, -kStraight}, {4, 0.02, 20}, kAsphalt});
    for (double z = 10; z > -kStraight; z -= 8) {  // centre-line dashes
        s.boxes.push_back({{-0.08, 0.02, z - 3}, {0.08, 0.03, z}, kPaint});
    }
    constexpr int kArcSteps = 48;  // road surface of the turn as flat quads
    for (int i = 0; i < kArcSteps; ++i) {
        const Pose p0 = poseAt(kStraight + kTurnLength * i / kArcSteps);
        const Pose p1 = poseAt(kStraight + kTurnLength * (i + 1) / kArcSteps);
        const Vec3 r0 = cross(p0.heading, Vec3{0, 1, 0}) * 4.0,
                   r1 = cross(p1.heading, Vec3{0, 1, 0}) * 4.0;
        const Vec3 up{0, 0.02, 0};
        addQuad(s, p0.position - r0 + up, p0.position + r0 + up, p1.position + r1 + up,
                p1.position - r1 + up, kAsphalt);
    }
}

void addTrees(Scene& s, SplitMix64& rng) {
    // Right verge, 60-105 m: the sun's ray crosses these crowns while the car covers 25-70 m.
    int i = 0;
    for (double z = -60; z > -105; z -= uniform(rng, 10, 14), ++i) {
        const Vec3 base{uniform(rng, 8, 12), 0, z};
        if (i % 3 == 1) {
            addRoundTree(s, base, uniform(rng, 7, 9));
        } else {
            addLeafTree(s, rng, base, uniform(rng, 8, 10), 110);
        }
    }
    // Left verge all along the straight (scenery; the sun is on the right).
    for (double z = 5; z > -kTunnelStart + 5; z -= uniform(rng, 9, 14)) {
        addLeafTree(s, rng, {uniform(rng, -14, -8), 0, z}, uniform(rng, 7, 10), 140);
    }
    // Both sides of the turn and the road beyond it.
    for (int k = 0; k < 10; ++k) {
        const Pose p = poseAt(kStraight + kTurnLength * (k + 0.5) / 8.0);
        const Vec3 left = cross(Vec3{0, 1, 0}, p.heading);
        const double side = k % 2 ? -1.0 : 1.0;
        addLeafTree(s, rng, p.position + left * (side * uniform(rng, 9, 13)), uniform(rng, 7, 10),
                    140);
    }
}

void addBuildingsAndPoles(Scene& s, SplitMix64& rng) {
    // Right, 44-70 m out: blocks whose roofs straddle the sun's ray (5.7-7.9 m high there), so the
    // sun blinks between them and grazes their roof edges.
    int index = 0;
    for (double z = -44; z > -70; ++index) {
        const double length = uniform(rng, 5, 7), gap = uniform(rng, 10, 13);
        const double height = index % 2 ? uniform(rng, 12, 16) : uniform(rng, 6, 7.5);
        s.boxes.push_back({{10, 0, z - length},
                           {uniform(rng, 13, 15), height, z},
                           kConcrete * uniform(rng, 0.7, 1.2)});
        z -= length + gap;
    }
    // Lamp posts on the right verge, 0.24 m thick: they slice across the disc before the tunnel.
    for (double z = -86; z > -116; z -= 7) {
        s.boxes.push_back({{6.0, 0, z - 0.12}, {6.24, 9, z + 0.12}, kPole});
    }
    // Left: scenery.
    for (double z = -20; z > -115; z -= 18) {
        s.boxes.push_back(
            {{-34, 0, z - 12}, {-20, uniform(rng, 10, 22), z}, kConcrete * uniform(rng, 0.6, 1.1)});
    }
    // Ahead after the turn (the road then runs toward -x).
    for (int k = 0; k < 6; ++k) {
        const double z = -150 - 22.0 * k, x = -120 - uniform(rng, 0, 30);
        s.boxes.push_back({{x - 14, 0, z - 14},
                           {x, uniform(rng, 12, 30), z},
                           kConcrete * uniform(rng, 0.6, 1.1)});
    }
}

void addTunnel(Scene& s) {
    const double z0 = -kTunnelEnd, z1 = -kTunnelStart;
    s.boxes.push_back({{-40, 0, z0}, {-5, kPortalHeight, z1}, kConcrete});  // left block
    s.boxes.push_back({{5, 0, z0}, {40, kPortalHeight, z1}, kConcrete});    // right block
    s.boxes.push_back({{-5, 6, z0}, {5, kPortalHeight, z1}, kConcrete});    // roof
}

}  // namespace

Scene buildWorld(int width, int height) {
    Scene s;
    s.width = width;
    s.height = height;
    s.sun = demoSun();
    SplitMix64 rng(2026);  // fixed: the same world on every run and platform
    addRoad(s);
    addTrees(s, rng);
    addBuildingsAndPoles(s, rng);
    addTunnel(s);
    return s;
}

SceneCamera cameraAt(double t) {
    const Pose p = poseAt(std::clamp(t, 0.0, 1.0) * kDriveLength);
    SceneCamera c;
    c.position = p.position + Vec3{0, kEyeHeight, 0};
    c.lookAt = c.position + p.heading * 20.0 + Vec3{0, 1.0, 0};  // eyes slightly up the road
    c.up = {0, 1, 0};
    c.fovYDeg = 60;
    c.nearPlane = 0.1;
    c.farPlane = 2000;
    return c;
}

SceneSun demoSun() {
    SceneSun sun;
    sun.direction = normalize(Vec3{0.30, 0.13, -1});
    sun.angularRadiusDeg = 1.5;
    sun.color = {1.0, 0.92, 0.8};
    sun.intensity = 2400;  // a low sun: 5 on a lit surface, a flare scale of 3.7 (Flare.h)
    return sun;
}

}  // namespace flarekit::demo
