// SPDX-License-Identifier: Apache-2.0
// The temporal filter: attack/release time constants, frame-rate independence, edge fade and
// exposure adaptation, against the closed forms of exponential smoothing.
#include <gtest/gtest.h>

#include <cmath>

#include "flarekit/Temporal.h"

using namespace flarekit;

namespace {
constexpr int kW = 1280, kH = 720;
const Point kCentre{640, 360};

TemporalParams noAdaptation() {
    TemporalParams p;
    p.adaptStrength = 0;
    return p;
}
}  // namespace

TEST(Temporal, FirstFrameStartsAtItsOwnValue) {
    TemporalFilter f(noAdaptation());
    EXPECT_DOUBLE_EQ(f.update(0.37, kCentre, true, kW, kH, 0.033).coverage, 0.37);
}

TEST(Temporal, AttackAndReleaseFollowTheirTimeConstants) {
    TemporalParams p = noAdaptation();
    p.attackSeconds = 0.1;
    p.releaseSeconds = 0.4;
    TemporalFilter rising(p), falling(p);
    rising.update(0, kCentre, true, kW, kH, 0);
    falling.update(1, kCentre, true, kW, kH, 0);
    // After one time constant the value has covered 1 - 1/e of the step, in any frame count.
    double up = 0, down = 0;
    for (int i = 0; i < 10; ++i) up = rising.update(1, kCentre, true, kW, kH, 0.01).coverage;
    for (int i = 0; i < 40; ++i) down = falling.update(0, kCentre, true, kW, kH, 0.01).coverage;
    EXPECT_NEAR(up, 1 - std::exp(-1.0), 1e-12);
    EXPECT_NEAR(down, std::exp(-1.0), 1e-12);
}

TEST(Temporal, FrameRateIndependent) {
    TemporalFilter at30(noAdaptation()), at120(noAdaptation());
    at30.update(0, kCentre, true, kW, kH, 0);
    at120.update(0, kCentre, true, kW, kH, 0);
    double a = 0, b = 0;
    for (int i = 0; i < 3; ++i) a = at30.update(1, kCentre, true, kW, kH, 1.0 / 30).coverage;
    for (int i = 0; i < 12; ++i) b = at120.update(1, kCentre, true, kW, kH, 1.0 / 120).coverage;
    EXPECT_NEAR(a, b, 1e-12);
}

TEST(Temporal, SmoothingDampsAlternatingNoise) {
    TemporalFilter f(noAdaptation());
    double minV = 1, maxV = 0;
    for (int i = 0; i < 120; ++i) {
        const double raw = i % 2 ? 0.55 : 0.45;  // +-0.05 frame-to-frame sample noise
        const double v = f.update(raw, kCentre, true, kW, kH, 1.0 / 30).coverage;
        if (i > 30) minV = std::min(minV, v), maxV = std::max(maxV, v);
    }
    EXPECT_LT(maxV - minV, 0.1 * 0.6);  // at least 40% less swing than the raw 0.1
}

TEST(Temporal, ZeroTimeConstantFollowsAtOnceAndNonFiniteCoverageIsZero) {
    TemporalParams p = noAdaptation();
    p.attackSeconds = p.releaseSeconds = 0;
    TemporalFilter f(p);
    f.update(0.2, kCentre, true, kW, kH, 0);
    EXPECT_DOUBLE_EQ(f.update(0.9, kCentre, true, kW, kH, 0.01).coverage, 0.9);
    EXPECT_DOUBLE_EQ(f.update(NAN, kCentre, true, kW, kH, 0.01).coverage, 0.0);
    EXPECT_DOUBLE_EQ(f.update(7.0, kCentre, true, kW, kH, 0.01).coverage, 1.0);
}

TEST(Temporal, EdgeFadeIsZeroAtTheEdgeOneBeyondTheBandAndSmoothBetween) {
    const double band = 0.1 * 720;  // 72 px
    EXPECT_DOUBLE_EQ(edgeFade({0, 360}, kW, kH, 0.1), 0.0);
    EXPECT_DOUBLE_EQ(edgeFade({-5, 360}, kW, kH, 0.1), 0.0);
    EXPECT_DOUBLE_EQ(edgeFade({640, 720}, kW, kH, 0.1), 0.0);
    EXPECT_DOUBLE_EQ(edgeFade({float(band), 360}, kW, kH, 0.1), 1.0);
    EXPECT_DOUBLE_EQ(edgeFade({640, 360}, kW, kH, 0.1), 1.0);
    EXPECT_NEAR(edgeFade({float(kW - band / 2), 360}, kW, kH, 0.1), 0.5, 1e-6);  // smoothstep(0.5)
    EXPECT_NEAR(edgeFade({640, float(band / 4)}, kW, kH, 0.1), 0.25 * 0.25 * (3 - 0.5), 1e-6);
    EXPECT_DOUBLE_EQ(edgeFade({1, 1}, kW, kH, 0.0), 1.0);  // no band: on until the edge
}

TEST(Temporal, SunBehindTheCameraOrOutsideTheFrameGivesNoFlare) {
    TemporalFilter f;
    EXPECT_DOUBLE_EQ(f.update(1, kCentre, false, kW, kH, 0).flareWeight, 0.0);
    EXPECT_DOUBLE_EQ(f.update(1, {1400, 300}, true, kW, kH, 0.03).flareWeight, 0.0);
    EXPECT_DOUBLE_EQ(f.update(1, kCentre, true, kW, kH, 0.03).flareWeight, 1.0);
}

TEST(Temporal, ExposureDimsWhileStaringAtTheSunAndRecovers) {
    TemporalParams p;
    p.adaptStrength = 0.6;
    p.adaptDarkenSeconds = 0.3;
    p.adaptBrightenSeconds = 1.5;
    p.attackSeconds = p.releaseSeconds = 0;  // coverage steps at once: only adaptation lags
    TemporalFilter f(p);
    EXPECT_DOUBLE_EQ(f.update(0, kCentre, true, kW, kH, 0).exposure,
                     1.0);  // hidden sun: no dimming
    double e = 1;
    for (int i = 0; i < 300; ++i)
        e = f.update(1, kCentre, true, kW, kH, 0.01).exposure;  // 10 time constants
    EXPECT_NEAR(e, 1 / 1.6, 1e-4);
    // One brighten time constant after the sun is hidden: 1/e of the way back, in log space.
    double back = e;
    for (int i = 0; i < 150; ++i) back = f.update(0, kCentre, true, kW, kH, 0.01).exposure;
    EXPECT_NEAR(std::log(back), std::log(e) * std::exp(-1.0), 1e-3);
    // The same sun in the corner of the frame dims less.
    TemporalFilter corner(p);
    const double cornerExposure = corner.update(1, {100, 100}, true, kW, kH, 0).exposure;
    EXPECT_GT(cornerExposure, 1 / 1.6);
    EXPECT_LT(cornerExposure, 1.0);
}

TEST(Temporal, ValidationNamesTheField) {
    TemporalParams p;
    p.guardBand = 0.9;
    const Status s = validateTemporalParams(p);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("guard-band"), std::string::npos) << s.error().message;
    p = {};
    p.releaseSeconds = NAN;
    EXPECT_FALSE(validateTemporalParams(p).ok());
    EXPECT_TRUE(validateTemporalParams({}).ok());
}
