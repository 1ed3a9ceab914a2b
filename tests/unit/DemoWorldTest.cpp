// SPDX-License-Identifier: Apache-2.0
// The demo world does what its story says, measured by the ray-cast ground truth: the sun
// flickers through the trees, vanishes in the tunnel, is clear after it, and leaves the frame
// in the turn.
#include <gtest/gtest.h>

#include <cmath>

#include "flarekit/Demo.h"
#include "flarekit/Visibility.h"

using namespace flarekit;

namespace {
//! Distances along the road (metres) as a fraction of the 230.85 m drive.
double at(double metres) {
    return metres / (175 + 40 * 80 * M_PI / 180);
}

VisibilityResult measure(const RaycastCaster& caster, double t) {
    const Scene view = demoScene(640, 360, t);
    auto r = caster.measure(view);
    EXPECT_TRUE(r.ok());
    return *r;
}
}  // namespace

TEST(DemoWorld, StoryBeatsHoldUnderTheRaycastTruth) {
    const RaycastCaster caster(demoScene(640, 360, 0));
    EXPECT_EQ(measure(caster, at(100)).coverage, 0.0);  // inside the tunnel
    EXPECT_EQ(measure(caster, at(135)).coverage, 1.0);  // clear straight after the exit
    const VisibilityResult end = measure(caster, 1.0);  // after the turn
    EXPECT_EQ(end.inFrame, 0.0);
    EXPECT_EQ(measure(caster, at(135)).inFrame, 1.0);
}

TEST(DemoWorld, SunFlickersThroughTheTreeCrowns) {
    const RaycastCaster caster(demoScene(640, 360, 0));
    // 30-70 m: the right-hand tree crowns cross the sun's ray. Partly visible on average, and
    // changing from one metre to the next.
    double sum = 0, change = 0, previous = -1;
    int partial = 0, n = 0;
    for (double s = 30; s <= 70; s += 1, ++n) {
        const double c = measure(caster, at(s)).coverage;
        sum += c;
        partial += c > 0.02 && c < 0.98;
        if (previous >= 0) change += std::abs(c - previous);
        previous = c;
    }
    EXPECT_GT(sum / n, 0.2);
    EXPECT_LT(sum / n, 0.9);
    EXPECT_GT(partial, n / 3);
    EXPECT_GT(change / (n - 1), 0.03);
}

TEST(DemoWorld, SameWorldEveryTime) {
    const Scene a = demoScene(320, 180, 0.3), b = demoScene(320, 180, 0.3);
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    ASSERT_FALSE(a.triangles.empty());
    EXPECT_EQ(a.triangles.back().a.x, b.triangles.back().a.x);
    EXPECT_EQ(a.camera.position.z, b.camera.position.z);
    EXPECT_LT(demoScene(320, 180, 0.5).camera.position.z, a.camera.position.z);  // driving on
}

TEST(Raycast, CasterReusedAcrossViewsMatchesOneShotCalls) {
    Scene s = demoScene(320, 180, 0.2);
    const RaycastCaster caster(s);
    for (double t : {0.1, 0.25, 0.6}) {
        s.camera = demoScene(320, 180, t).camera;
        auto reused = caster.measure(s), fresh = raycastVisibility(s);
        ASSERT_TRUE(reused.ok() && fresh.ok());
        EXPECT_EQ(reused->coverage, fresh->coverage);
        EXPECT_EQ(reused->inFrame, fresh->inFrame);
    }
}
