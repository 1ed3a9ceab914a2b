// SPDX-License-Identifier: Apache-2.0
// Fast approximations for per-pixel maths. Each states its error bound, which a unit test
// checks against the standard library.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flarekit {

//! atan2(y, x) in (-pi, pi], absolute error below 2e-6 rad (tests/unit/FastMathTest.cpp):
//! at 1000 pixels from an element's centre that is 0.002 px, far below antialiasing. Octant
//! reduction to z in [0, 1] and an odd minimax polynomial for atan(z) (degree 11).
inline float fastAtan2(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float hi = std::max(ax, ay), lo = std::min(ax, ay);
    if (hi == 0.f) return 0.f;
    const float z = lo / hi, z2 = z * z;
    float a =
        z *
        (0.99997726f +
         z2 * (-0.33262347f +
               z2 * (0.19354346f + z2 * (-0.11643287f + z2 * (0.05265332f + z2 * -0.01172120f)))));
    if (ay > ax) a = 0.5f * std::numbers::pi_v<float> - a;
    if (x < 0.f) a = std::numbers::pi_v<float> - a;
    return y < 0.f ? -a : a;
}

//! An upper bound of asin(s) for s in [0, 1], within 0.4% of it: s (1 + s^2/5) up to s = 0.5
//! (asin(s)/s = 1 + s^2/6 + 3 s^4/40 + ... stays below 1 + s^2/5 there), asin above.
inline float asinUpperBound(float s) {
    if (s <= 0.5f) return s * (1.000001f + 0.2f * s * s);  // 1e-6 covers float rounding
    return s >= 1.f ? 0.5f * std::numbers::pi_v<float> : std::asin(s);
}

}  // namespace flarekit
