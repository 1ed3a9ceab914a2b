// SPDX-License-Identifier: Apache-2.0
// The sun's cone of directions (half-angle = its angular radius around sun.direction): an
// orthonormal frame around the axis, the equal-area map from the square [-1, 1]^2 into the cone
// (ray-cast sampling) and the rim's directions (the projected disc's outline).
#pragma once

#include <cmath>
#include <numbers>

#include "flarekit/Scene.h"

namespace flarekit::occlusion {

struct SunCone {
    explicit SunCone(const SceneSun& sun)
        : SunCone(sun.direction, sun.angularRadiusDeg * std::numbers::pi / 180.0) {}
    //! The cone around `direction` (any length) of half-angle `radiusRadians`.
    SunCone(Vec3 direction, double radiusRadians)
        : axis(normalize(direction)), radius(radiusRadians), oneMinusCos(1.0 - std::cos(radius)) {
        const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        t1 = normalize(cross(axis, helper));
        t2 = cross(axis, t1);
    }

    //! (a, b) in [-1, 1]^2 to a direction in the cone, uniform over solid angle when (a, b) is
    //! uniform: Shirley and Chiu's concentric map (1997) to the unit disc, then the disc to the
    //! cone by 1 - cos(theta) = rho^2 (1 - cos(radius)); both maps are equal-area.
    Vec3 fromSquare(double a, double b) const {
        constexpr double kPi = std::numbers::pi;
        double rho = 0, phi = 0;
        if (a == 0 && b == 0) {
            rho = phi = 0;
        } else if (std::abs(a) > std::abs(b)) {
            rho = a;
            phi = (kPi / 4) * (b / a);
        } else {
            rho = b;
            phi = kPi / 2 - (kPi / 4) * (a / b);
        }
        const double cosTheta = 1.0 - rho * rho * oneMinusCos;
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const double sign =
            rho < 0 ? -1.0 : 1.0;  // rho may be negative: the sign folds into the angle
        return cosTheta * axis + (sign * sinTheta) * (std::cos(phi) * t1 + std::sin(phi) * t2);
    }

    //! The rim direction at angle phi around the axis.
    Vec3 rim(double phi) const {
        return std::cos(radius) * axis +
               std::sin(radius) * (std::cos(phi) * t1 + std::sin(phi) * t2);
    }

    Vec3 axis, t1, t2;
    double radius, oneMinusCos;
};

}  // namespace flarekit::occlusion
