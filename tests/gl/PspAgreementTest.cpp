// SPDX-License-Identifier: Apache-2.0
// The PSP emulation's coverage byte against the GL `burnout` method: the same scene
// at the PSP's 480x272, its occluders ray-cast into the emulator's mask. The GL method
// measures the sun's disc (radius 7 px here, the PSP's 14x14 region), the PSP the square
// region with the chain's uneven taps, so they agree to the PSP's quantisation: one column of
// the 14x14 mask is 1/14 = 0.071.
#include <gtest/gtest.h>

#include "GlTestContext.h"
#include "GpuMeasure.h"
#include "flarekit/Psp.h"

using namespace flarekit;

namespace {
Scene pspScene() {
    Scene s;
    s.width = psp::kScreenWidth;
    s.height = psp::kScreenHeight;
    s.camera.position = {0, 1.7, 0};
    s.sun.direction = normalize(Vec3{0, 0.25, -1});
    s.sun.angularRadiusDeg = 1.7;  // 7 px at 480x272 with a 60-degree field of view
    s.camera.lookAt = s.camera.position + s.sun.direction * 20.0 + Vec3{3, -2, 0};
    return s;
}
}  // namespace

TEST(PspAgreement, BurnoutByteMatchesTheGlBurnoutMethod) {
    test::glContext();
    std::vector<std::pair<std::string, Scene>> scenes;
    scenes.emplace_back("visible", pspScene());
    Scene hidden = pspScene();
    hidden.boxes.push_back({{-20, -10, -40}, {20, 30, -30}, {0.3, 0.3, 0.3}});
    scenes.emplace_back("hidden", hidden);
    Scene half = pspScene();  // the plane x = 0 contains the sun direction: half the disc
    half.boxes.push_back({{0, -50, -40}, {60, 80, -35}, {0.3, 0.3, 0.3}});
    scenes.emplace_back("half", half);
    Scene sphere = pspScene();
    sphere.spheres.push_back(
        {sphere.camera.position + normalize(Vec3{0.012, 0.25, -1}) * 10.0, 0.15, {0.3, 0.3, 0.3}});
    scenes.emplace_back("sphere", sphere);
    for (const auto& [name, scene] : scenes) {
        auto gl = test::measureGpuCoverage("burnout", scene);
        ASSERT_TRUE(gl.ok()) << name;
        auto in = psp::pspInputFromScene(scene);
        ASSERT_TRUE(in.ok()) << name;
        auto r = psp::runPspFrame(psp::PspTrick::Burnout, *in);
        ASSERT_TRUE(r.ok()) << name;
        ASSERT_TRUE(r->sunInFrame) << name;
        EXPECT_NEAR(r->coverageByte / 255.0, *gl, 0.08)
            << name << ": PSP byte " << r->coverageByte << ", GL " << *gl;
    }
}
