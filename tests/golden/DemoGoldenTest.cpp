// SPDX-License-Identifier: Apache-2.0
// Golden frames of the demo drive at 320x180 through headless GL: the CPU flare path
// (raycast coverage) and the GPU path (compute coverage, flare, smoothing and tone map on the
// GPU). Rasterisation on a different Mesa or GPU may move edge pixels, so a few levels are
// allowed at a pixel, with a small mean.
#include "GoldenImage.h"

#include "GlTestContext.h"
#include "flarekit/Demo.h"
#include "flarekit/gl/DemoAnimation.h"

using namespace flarekit;

namespace {

void checkDrive(const std::string& method, std::initializer_list<int> frames) {
    DemoSettings settings;
    settings.width = 320, settings.height = 180, settings.frames = 24, settings.method = method;
    settings.fps = 3;  // 24 frames over the whole 8 s drive
    settings.raycastSamplesPerSide = 32;
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    auto demo = DemoAnimation::create(settings, *preset);
    ASSERT_TRUE(demo.ok()) << demo.error().message;
    int next = 0;
    for (int want : frames) {
        for (; next <= want; ++next) {
            auto frame = demo->next();
            ASSERT_TRUE(frame.ok()) << frame.error().message;
            if (next == want) {
                golden::expectMatches("demo-" + method + "-" + std::to_string(want), frame->image,
                                      {6, 0.1});
            }
        }
    }
}

}  // namespace

TEST(GoldenDemo, RaycastDriveFrames) {
    flarekit::test::glContext();
    checkDrive("raycast", {2, 11, 20});
}

TEST(GoldenDemo, ComputeDriveFrames) {
    flarekit::test::glContext();
    checkDrive("compute", {2, 11, 20});
}
