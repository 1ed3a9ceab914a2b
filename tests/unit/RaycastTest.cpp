// SPDX-License-Identifier: Apache-2.0
// The ray-cast ground truth against closed-form coverages (architecture.md's definition:
// the visible fraction of the sun's cone, uniform over solid angle).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/Parallel.h"
#include "flarekit/Visibility.h"
#include "occlusion/raycast/Intersect.h"
#include "occlusion/raycast/SceneBvh.h"

using namespace flarekit;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;
// The ground truth's own bound: with the default sample count the error is below 0.005 on any
// scene.
constexpr double kTolerance = 0.005;

Scene sunAhead(double angularRadiusDeg) {
    Scene s;
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, -1};
    s.camera.up = {0, 1, 0};
    s.sun.direction = {0, 0, -1};
    s.sun.angularRadiusDeg = angularRadiusDeg;
    return s;
}

double coverage(const Scene& s) {
    auto r = raycastVisibility(s);
    EXPECT_TRUE(r.ok());
    return r->coverage;
}

}  // namespace

TEST(Raycast, EmptySkyIsFullyVisible) {
    Scene s = sunAhead(1.5);
    EXPECT_EQ(coverage(s), 1.0);
    s.sun.direction = normalize(Vec3{0.3, 0.5, -1});
    EXPECT_EQ(coverage(s), 1.0);
}

TEST(Raycast, SphereOverTheWholeDiscHidesIt) {
    Scene s = sunAhead(1.5);
    s.spheres.push_back({{0, 0, -50}, 5.0, {}});  // angular radius asin(5/50) = 5.7 deg > 1.5
    EXPECT_EQ(coverage(s), 0.0);
}

TEST(Raycast, ConcentricSphereHidesTheExactCapFraction) {
    // A sphere of angular radius beta centred on the sun hides the cap 1 - cos(beta) of the
    // sun's 1 - cos(alpha): coverage = 1 - (1 - cos beta) / (1 - cos alpha).
    for (double beta : {1.0, 2.5, 4.0}) {
        Scene s = sunAhead(5.0);
        const double distance = 100;
        s.spheres.push_back({{0, 0, -distance}, distance * std::sin(beta * kDeg), {}});
        const double want = 1 - (1 - std::cos(beta * kDeg)) / (1 - std::cos(5.0 * kDeg));
        EXPECT_NEAR(coverage(s), want, kTolerance) << "beta " << beta;
    }
}

TEST(Raycast, BoxEdgeThroughTheCentreHidesHalf) {
    for (double alpha : {0.5, 1.5, 10.0}) {
        Scene s = sunAhead(alpha);
        s.boxes.push_back({{-1000, -1000, -60}, {0, 1000, -50}, {}});  // everything with x < 0
        EXPECT_NEAR(coverage(s), 0.5, kTolerance) << alpha;
    }
    // The same with a tilted sun and a box edge along the sun's direction.
    Scene t = sunAhead(2.0);
    t.sun.direction = normalize(Vec3{0, 0.6, -1});
    t.boxes.push_back({{-1000, -1000, -1000}, {0, 1000, -20}, {}});
    EXPECT_NEAR(coverage(t), 0.5, kTolerance);
}

TEST(Raycast, OffsetSphereHidesTheLensArea) {
    // Small angles, so the sky is nearly flat there: two discs of equal angular radius r whose
    // centres are r apart overlap in the lens 2 r^2 acos(1/2) - (r/2) sqrt(3 r^2).
    const double r = 2.0 * kDeg, distance = 200;
    Scene s = sunAhead(2.0);
    const Vec3 dir = {std::sin(r), 0, -std::cos(r)};
    s.spheres.push_back({dir * distance, distance * std::sin(r), {}});
    const double lens = 2 * std::acos(0.5) - 0.5 * std::sqrt(3.0);  // over r^2
    EXPECT_NEAR(coverage(s), 1 - lens / kPi, kTolerance);
}

TEST(Raycast, CameraMovingAlongTheSunDirectionWithoutOccludersKeepsFullCoverage) {
    Scene s = sunAhead(1.5);
    s.sun.direction = normalize(Vec3{0.2, 0.3, -1});
    s.spheres.push_back({{0, -20, 0}, 5, {}});  // below, never in the sun's way
    for (double k : {0.0, 10.0, 1000.0}) {
        s.camera.position = s.sun.direction * k;
        s.camera.lookAt = s.camera.position + Vec3{0, 0, -1};
        EXPECT_EQ(coverage(s), 1.0) << k;
    }
}

TEST(Raycast, DeterministicAndThreadIndependent) {
    Scene s = sunAhead(3.0);
    s.spheres.push_back({{0.8, 0.3, -30}, 1.0, {}});
    const double a = coverage(s);
    double b = 0;
    {
        ThreadLimit one(1);
        b = coverage(s);
    }
    EXPECT_EQ(a, b);
    EXPECT_GT(a, 0.0);
    EXPECT_LT(a, 1.0);
}

TEST(Raycast, InFrameFraction) {
    Scene s = sunAhead(1.5);
    auto ahead = raycastVisibility(s);
    EXPECT_EQ(ahead->inFrame, 1.0);
    s.sun.direction = {0, 0, 1};  // behind the camera
    EXPECT_EQ(raycastVisibility(s)->inFrame, 0.0);
    // Sun centred on the right frame edge: half the disc in frame.
    Scene edge = sunAhead(1.0);
    const double halfX = std::atan(std::tan(30 * kDeg) * 640.0 / 360.0);
    edge.sun.direction = {std::sin(halfX), 0, -std::cos(halfX)};
    EXPECT_NEAR(raycastVisibility(edge)->inFrame, 0.5, kTolerance);
}

TEST(Raycast, BvhAgreesWithBruteForceOnFoliage) {
    // 3000 small random triangles plus spheres and boxes: the BVH answers like a linear scan.
    Scene s = sunAhead(5.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-3, 3), depth(-40, -10), small(-0.3, 0.3);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 c{u(rng), u(rng), depth(rng)};
        s.triangles.push_back({c + Vec3{small(rng), small(rng), small(rng)},
                               c + Vec3{small(rng), small(rng), small(rng)},
                               c + Vec3{small(rng), small(rng), small(rng)},
                               {}});
    }
    for (int i = 0; i < 30; ++i) s.spheres.push_back({{u(rng), u(rng), depth(rng)}, 0.2, {}});
    for (int i = 0; i < 30; ++i) {
        const Vec3 lo{u(rng), u(rng), depth(rng)};
        s.boxes.push_back({lo, lo + Vec3{0.2, 0.3, 0.4}, {}});
    }
    const SceneBvh bvh(s);
    EXPECT_EQ(bvh.primitiveCount(), 3060u);
    std::uniform_real_distribution<double> dir(-0.1, 0.1);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 d{dir(rng), dir(rng), -1};
        bool brute = false;
        for (const Triangle& t : s.triangles) brute = brute || intersect::triangle({0, 0, 0}, d, t);
        for (const Sphere& sp : s.spheres) brute = brute || intersect::sphere({0, 0, 0}, d, sp);
        const Vec3 inv{1 / d.x, 1 / d.y, 1 / d.z};
        for (const Box& b : s.boxes)
            brute = brute || intersect::slabs({0, 0, 0}, inv, b.min, b.max);
        ASSERT_EQ(bvh.occluded({0, 0, 0}, d), brute) << i;
        hits += brute;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_LT(hits, 19000);
}

TEST(Raycast, CameraInsideABoxOrSphereIsOccluded) {
    Scene s = sunAhead(1.5);
    s.boxes.push_back({{-1, -1, -1}, {1, 1, 1}, {}});
    EXPECT_EQ(coverage(s), 0.0);
    Scene t = sunAhead(1.5);
    t.spheres.push_back({{0, 0, 0}, 2, {}});
    EXPECT_EQ(coverage(t), 0.0);
}

// The ground occludes like any object. With the eye at the ground and the ground reaching far
// away, the horizon is a straight line through eye level, so a sun of angular radius r whose
// centre is at elevation e (|e| < r) keeps the circular segment above it: a share
// (theta - sin theta cos theta) / pi of the disc, cos theta = -e / r. Wholly below the
// horizon it is hidden, wholly above it is not.
TEST(Raycast, GroundHidesASunBelowTheHorizon) {
    Scene s;
    s.camera.position = {0, 0.001, 0};  // eye at the ground: the horizon is the eye level
    s.camera.lookAt = {0, 0, -10};
    s.camera.farPlane = 1e6;  // the ground reaches out to camera.far
    s.sun.angularRadiusDeg = 1.0;
    s.ground = Ground{0.0, {0.2, 0.2, 0.2}};
    RaycastOptions o;
    o.samplesPerSide = 256;
    auto at = [&](double elevationDeg) {
        const double e = elevationDeg * 3.14159265358979323846 / 180.0;
        s.sun.direction = {0, std::sin(e), -std::cos(e)};
        auto r = raycastVisibility(s, o);
        EXPECT_TRUE(r.ok());
        return r ? r->coverage : -1.0;
    };
    EXPECT_EQ(at(-3.0), 0.0);
    EXPECT_NEAR(at(3.0), 1.0, 1e-9);
    // Centred on the horizon: half the disc (the ground's far edge is 1e6 m away, 1e-9 rad down).
    EXPECT_NEAR(at(0.0), 0.5, 0.01);
    // Half a radius above: the circular segment above the line y = -r/2.
    const double theta = std::acos(-0.5);
    EXPECT_NEAR(at(0.5), (theta - std::sin(theta) * std::cos(theta)) / 3.14159265358979323846,
                0.01);
    s.ground.reset();
    EXPECT_NEAR(at(-3.0), 1.0, 1e-9);  // no ground, nothing in the way
}
