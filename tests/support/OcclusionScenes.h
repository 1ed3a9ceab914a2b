// SPDX-License-Identifier: Apache-2.0
// The generated scenes that GPU visibility methods are judged on against the ray-cast truth
// : sun fully visible, fully hidden, half behind a box edge, behind foliage of many
// small spheres, behind a thin pole, near the frame edge, small and large angular radii, and
// off screen. 640x360, deterministic.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "flarekit/Scene.h"

namespace flarekit::test {

struct OcclusionCase {
    std::string name;
    Scene scene;
};

namespace detail {
inline Scene base(Vec3 sunDirection, double radiusDeg) {
    Scene s;
    s.width = 640;
    s.height = 360;
    s.camera.position = {0, 1.7, 0};
    s.sun.direction = normalize(sunDirection);
    s.sun.angularRadiusDeg = radiusDeg;
    s.camera.lookAt = s.camera.position + s.sun.direction * 20.0;  // sun at the centre
    return s;
}
//! Unit vectors perpendicular to d.
inline void perpendiculars(Vec3 d, Vec3& a, Vec3& b) {
    const Vec3 helper = std::abs(d.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    a = normalize(cross(d, helper));
    b = cross(d, a);
}
inline double uniform01(unsigned& state) {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
}
}  // namespace detail

inline std::vector<OcclusionCase> occlusionCases() {
    using namespace detail;
    std::vector<OcclusionCase> cases;
    const Vec3 dirs[] = {{0.2, 0.3, -1}, {-0.4, 0.15, -1}, {0.05, 0.6, -1}};
    for (double radius : {1.5, 3.0}) {
        for (int k = 0; k < 3; ++k) {
            const std::string tag = std::string("r") + std::to_string(int(radius * 10)) +
                                    std::string("-d") + std::to_string(k);
            Scene s = base(dirs[k], radius);
            cases.push_back({std::string("visible-") + tag, s});
            Vec3 a, b;
            perpendiculars(s.sun.direction, a, b);
            const Vec3 eye = s.camera.position;
            // Fully hidden: a sphere on the axis, far bigger than the cone.
            Scene hidden = s;
            hidden.spheres.push_back({eye + s.sun.direction * 30.0, 5.0, {0.3, 0.3, 0.3}});
            cases.push_back({std::string("hidden-") + tag, hidden});
            // A sphere covering part of the disc: offset so its rim crosses the disc.
            for (double offset : {0.6, 1.0}) {
                Scene part = s;
                const double d = 40, r = 1.0, alphaRad = radius * M_PI / 180;
                part.spheres.push_back(
                    {eye + s.sun.direction * d +
                         a * (r + offset * (alphaRad * d - r) + 0.3 * alphaRad * d * offset),
                     r,
                     {0.3, 0.3, 0.3}});
                cases.push_back({std::string("sphere-part") + std::to_string(int(offset * 10)) +
                                     std::string("-") + tag,
                                 part});
            }
            // Foliage: 150 small spheres scattered around the axis 15-25 m out.
            Scene leaves = s;
            unsigned state = 7u + unsigned(k) * 31u + unsigned(radius * 10);
            const double spread = std::tan(radius * M_PI / 180) * 1.3;
            for (int i = 0; i < 150; ++i) {
                const double dist = 15 + 10 * uniform01(state);
                const double u = (2 * uniform01(state) - 1) * spread * dist,
                             v = (2 * uniform01(state) - 1) * spread * dist;
                leaves.spheres.push_back({eye + s.sun.direction * dist + a * u + b * v,
                                          0.04 + 0.06 * uniform01(state),
                                          {0.1, 0.3, 0.1}});
            }
            cases.push_back({std::string("foliage-") + tag, leaves});
            // A thin pole across the disc: 8 cm, 10 m out (2.5 px), through the centre.
            Scene pole = s;
            const Vec3 c = eye + s.sun.direction * 10.0;
            pole.boxes.push_back(
                {c - Vec3{0.04, 5, 0.04}, c + Vec3{0.04, 5, 0.04}, {0.2, 0.2, 0.2}});
            cases.push_back({std::string("pole-") + tag, pole});
        }
    }
    // Half behind a box edge: the plane x = 0 through the eye contains the sun direction, so
    // a box filling x > 0 hides exactly half of the disc.
    for (double radius : {1.5, 3.0}) {
        for (double elevation : {0.1, 0.4}) {
            Scene s = base({0, elevation, -1}, radius);
            s.camera.position = {0, 1.7, 0};
            s.boxes.push_back({{0, -50, -40}, {60, 80, -35}, {0.3, 0.3, 0.3}});
            cases.push_back({std::string("half-box-r") + std::to_string(int(radius * 10)) +
                                 std::string("-e") + std::to_string(int(elevation * 10)),
                             s});
        }
    }
    // Near the frame edge: the camera turned so the disc sits 20 px inside the right edge.
    for (double radius : {1.5, 3.0}) {
        Scene s = base({0.2, 0.3, -1}, radius);
        const double pxPerRad = 180 / std::tan(M_PI / 6);
        const double tanHalfX = std::tan(M_PI / 6) * 640.0 / 360.0;
        const double rimPx = radius * M_PI / 180 * pxPerRad;
        const double x =
            (320 - 20 - rimPx) / 320 * tanHalfX;  // tangent of the sun's azimuth in the view
        Vec3 a, b;
        detail::perpendiculars(s.sun.direction, a, b);
        const Vec3 right = normalize(cross(s.sun.direction, Vec3{0, 1, 0}));
        s.camera.lookAt = s.camera.position + normalize(s.sun.direction - right * x) * 20.0;
        Scene edge = s;
        edge.spheres.push_back({s.camera.position + s.sun.direction * 40.0 +
                                    a * (std::tan(radius * M_PI / 180) * 40 * 0.8),
                                1.2,
                                {0.3, 0.3, 0.3}});
        cases.push_back({std::string("edge-r") + std::to_string(int(radius * 10)), s});
        cases.push_back({std::string("edge-part-r") + std::to_string(int(radius * 10)), edge});
    }
    // Small and large suns, part-covered.
    for (double radius : {0.6, 5.0}) {
        Scene s = base({0.1, 0.25, -1}, radius);
        Vec3 a, b;
        detail::perpendiculars(s.sun.direction, a, b);
        s.spheres.push_back(
            {s.camera.position + s.sun.direction * 30.0 + a * (std::tan(radius * M_PI / 180) * 30),
             std::tan(radius * M_PI / 180) * 30 * 0.9,
             {0.3, 0.3, 0.3}});
        cases.push_back({std::string("size-r") + std::to_string(int(radius * 10)), s});
    }
    return cases;
}

//! A pole thinner than a pixel (3 cm at 10 m: 0.9 px at 640x360) across a 1.5-degree sun: the
//! case where every method that reads one depth sample per pixel (or per sun-map texel) is
//! off by the pole's rasterised width; only MSAA samples resolve it.
inline Scene subpixelPole() {
    Scene s = detail::base({0.2, 0.3, -1}, 1.5);
    const Vec3 c = s.camera.position + s.sun.direction * 10.0;
    s.boxes.push_back({c - Vec3{0.015, 5, 0.015}, c + Vec3{0.015, 5, 0.015}, {0.2, 0.2, 0.2}});
    return s;
}

//! A sun behind the camera's right shoulder (out of frame), half behind a box edge: only a
//! method with its own camera (texture-mask) can measure it.
inline Scene offscreenHalfHidden() {
    Scene s = detail::base({0, 0.2, -1}, 2.0);
    s.camera.lookAt = s.camera.position + Vec3{-1, 0, 0} * 20.0;  // looking left, sun to the right
    s.boxes.push_back({{0, -50, -40}, {60, 80, -35}, {0.3, 0.3, 0.3}});
    return s;
}

}  // namespace flarekit::test
