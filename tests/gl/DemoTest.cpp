// SPDX-License-Identifier: Apache-2.0
// The demo animation end to end on the GL backend: frames of the requested size in order,
// the temporal filter applied to the method's coverage, bad settings rejected.
#include <gtest/gtest.h>

#include "GlTestContext.h"
#include "flarekit/Demo.h"
#include "flarekit/gl/DemoAnimation.h"

using namespace flarekit;

namespace {
Preset classic() {
    auto p = loadPreset("tanczos-classic");
    EXPECT_TRUE(p.ok());
    return *p;
}

//! The default drive at a small size and frame count.
DemoSettings sized(int width, int height, int frames) {
    DemoSettings settings;
    settings.width = width, settings.height = height, settings.frames = frames;
    return settings;
}
}  // namespace

TEST(Demo, RendersEveryFrameInOrderThenStops) {
    test::glContext();
    DemoSettings settings = sized(160, 90, 8);
    settings.fps = 1;  // the first 8 s: the whole drive, a frame a second
    settings.temporal.attackSeconds = settings.temporal.releaseSeconds = 0;  // smoothed == raw
    auto demo = DemoAnimation::create(settings, classic());
    ASSERT_TRUE(demo.ok()) << demo.error().message;
    EXPECT_GT(demo->primitiveCount(), 3000u);  // foliage triangles, trunks, buildings, road
    for (int i = 0; i < 8; ++i) {
        auto frame = demo->next();
        ASSERT_TRUE(frame.ok()) << frame.error().message;
        EXPECT_EQ(frame->image.width(), 160);
        EXPECT_EQ(frame->image.height(), 90);
        EXPECT_DOUBLE_EQ(frame->time, double(i));
        EXPECT_DOUBLE_EQ(frame->temporal.coverage, frame->rawCoverage);
        for (std::size_t k = 0; k < frame->image.pixelCount() * 4; ++k) {
            const float v = frame->image.data()[k];
            ASSERT_TRUE(v >= 0.f && v <= 1.f) << "tone-mapped output must be in [0, 1]";
        }
    }
    EXPECT_FALSE(demo->next().ok());
}

TEST(Demo, BadSettingsAreRejected) {
    test::glContext();
    DemoSettings s;
    s.method = "telepathy";
    auto a = DemoAnimation::create(s, classic());
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().message.find("method"), std::string::npos);
    s = {};
    s.frames = 0;
    EXPECT_FALSE(DemoAnimation::create(s, classic()).ok());
    s = {};
    s.width = 8;
    EXPECT_FALSE(DemoAnimation::create(s, classic()).ok());
    s = {};
    s.temporal.guardBand = -1;
    EXPECT_FALSE(DemoAnimation::create(s, classic()).ok());
}

// --frames at the demo's frame rate shortens the drive instead of squeezing it: 12 frames at
// 30 fps are the first 0.4 s, at the speed of the full drive.
TEST(Demo, FewerFramesAreAShorterDriveAtTheSameFrameRate) {
    test::glContext();
    const DemoSettings settings = sized(64, 36, 12);
    auto demo = DemoAnimation::create(settings, classic());
    ASSERT_TRUE(demo.ok()) << demo.error().message;
    double last = -1;
    for (int i = 0; i < 12; ++i) {
        auto frame = demo->next();
        ASSERT_TRUE(frame.ok());
        last = frame->time;
    }
    EXPECT_DOUBLE_EQ(last, 11.0 / 30.0);
}
