// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>

#include "core/FastMath.h"

using namespace flarekit;

TEST(FastMath, Atan2IsWithinItsStatedErrorEverywhere) {
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double angle = -M_PI + 2 * M_PI * (i + 0.5) / 200000;
        for (double r : {1e-3, 1.0, 777.0}) {
            const float x = float(r * std::cos(angle)), y = float(r * std::sin(angle));
            worst = std::max(worst,
                             std::abs(double(fastAtan2(y, x)) - std::atan2(double(y), double(x))));
        }
    }
    EXPECT_LT(worst, 2e-6);
    EXPECT_EQ(fastAtan2(0.f, 0.f), 0.f);
    EXPECT_NEAR(fastAtan2(0.f, -1.f), M_PI, 1e-6);
    EXPECT_NEAR(fastAtan2(-1.f, 0.f), -M_PI / 2, 1e-6);
}

TEST(FastMath, AsinUpperBoundIsAnUpperBoundAndTight) {
    for (int i = 0; i <= 100000; ++i) {
        const float s = float(i) / 100000.f;
        const float bound = asinUpperBound(s), exact = std::asin(s);
        ASSERT_GE(bound, exact) << s;
        ASSERT_LE(bound, exact * 1.004f + 1e-7f) << s;
    }
}
