// SPDX-License-Identifier: Apache-2.0
// The engine API over time and on screen: its per-light temporal filter against
// TemporalFilter, its instanced flare against renderFlare, and an off-screen light kept
// measured by a guard band with its edge streak lit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include <epoxy/egl.h>

#include "DepthPass.h"
#include "EngineTesting.h"
#include "GlTestContext.h"
#include "LightScenes.h"
#include "flarekit/Flare.h"
#include "flarekit/SunFlare.h"
#include "flarekit/Temporal.h"
#include "flarekit/Visibility.h"
#include "flarekit/flarekit.h"
#include "flarekit/flarekit.hpp"
#include "flarekit/gl/Render.h"
#include "scene/SceneTargets.h"

using namespace flarekit;
using namespace flarekit::test;

TEST(Engine, TemporalFilterMatchesTheCpuFilterPerLight) {
    Scene scene = wallScene();
    EnginePtr e = makeEngine(4);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    Scene open = scene;
    open.boxes.clear();
    const DepthPass walled(scene), clear(open);
    TemporalFilter cpu[4];
    const double dts[] = {1 / 60.0, 0.05, 0.02, 0.2, 1 / 30.0};
    const bool wall[] = {false, true, false, true, false};
    for (int frame = 0; frame < 5; ++frame) {
        fk_frame f = frameFor(scene, target, {0, 0, scene.width, scene.height},
                              FK_DEPTH_MINUS_ONE_TO_ONE, float(dts[frame]));
        (wall[frame] ? walled : clear).draw(target, f);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "depth pass";
        ASSERT_EQ(fk_engine_occlusion(e.get(), &f, lights.data(), 4), 0);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "occlusion";
        std::vector<float> raw(4), filtered(4);
        ASSERT_EQ(fk_engine_read_view(e.get(), 0, raw.data(), nullptr, filtered.data(), 4), 4);
        std::vector<float> texture(std::size_t(4) * FK_MAX_VIEWS);
        std::vector<float> all(std::size_t(4) * FK_MAX_VIEWS);
        glGetTextureImage(fk_engine_coverage_texture(e.get()), 0, GL_RED, GL_FLOAT,
                          GLsizei(all.size() * sizeof(float)), all.data());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        for (int i = 0; i < 4; ++i) {
            const TemporalState st =
                cpu[i].update(raw[std::size_t(i)], {160, 90}, true, 320, 180, float(dts[frame]));
            EXPECT_NEAR(filtered[std::size_t(i)], st.coverage, 1e-5) << "frame " << frame;
            EXPECT_EQ(all[std::size_t(i)], filtered[std::size_t(i)]);  // row 0: view 0
        }
    }
}

TEST(Engine, FlareOfAFullyVisibleSunMatchesTheCpuSpriteFlare) {
    Scene scene;
    scene.width = 640, scene.height = 360;
    scene.camera.position = {0, 0, 0};
    scene.camera.lookAt = {0, 0, -1};
    scene.sun.direction = normalize(Vec3{0.2, 0.1, -1});
    scene.sun.angularRadiusDeg = 0.5;
    scene.sun.color = {1, 1, 1};
    scene.sun.intensity = 4000;
    EnginePtr e = makeEngine(1);
    const int preset = fk_engine_load_preset(e.get(), "tanczos-classic");
    ASSERT_GE(preset, 0) << fk_error(e.get());
    const std::vector<fk_light> light = engineLights(scene, preset);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_MINUS_ONE_TO_ONE);
    const float one = 1.f;
    glClearTexImage(target.depth.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, light.data(), 1), 0);
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, scene.width, scene.height);
    auto fb = gl::makeFramebuffer(color.get());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    ASSERT_EQ(fk_engine_draw(e.get(), &frame, light.data(), 1, fb->get()), 0) << fk_error(e.get());
    auto gpu = gl::readTextureRgba(color.get(), scene.width, scene.height);
    ASSERT_TRUE(gpu.ok());

    Image cpu(scene.width, scene.height);
    auto presetData = loadPreset("tanczos-classic");
    ASSERT_TRUE(presetData.ok());
    Point sun;
    ASSERT_TRUE(projectDirection(scene, scene.sun.direction, sun));
    renderFlare(cpu, *presetData, sun, sunFlareScale(scene));
    double gpuSum = 0, cpuSum = 0, diff = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float g = c == 0   ? gpu->at(x, y).r
                                : c == 1 ? gpu->at(x, y).g
                                         : gpu->at(x, y).b;
                const float k = c == 0 ? cpu.at(x, y).r : c == 1 ? cpu.at(x, y).g : cpu.at(x, y).b;
                gpuSum += g;
                cpuSum += k;
                diff += std::abs(g - k);
            }
    ASSERT_GT(cpuSum, 0);
    EXPECT_NEAR(gpuSum / cpuSum, 1.0, 0.02);  // the same energy (flux model, element textures)
    EXPECT_LT(diff / cpuSum, 0.1);            // in the same places (bilinear sub-pixel shifts)
}

TEST(Engine, AGuardBandKeepsALightJustOffScreenMeasuredAndItsEdgeStreakLit) {
    // A 640x360 view inside a depth texture with a 64-pixel guard band all round, rendered with
    // the view's projection extended over the band. A sphere light 30 px past the right edge,
    // half behind a pole.
    glContext();
    Scene scene;
    scene.width = 640, scene.height = 360;
    scene.camera.position = {0, 0, 0};
    scene.camera.lookAt = {0, 0, -1};
    scene.sun.intensity = 0;
    const double halfWidth = std::tan(30.0 * M_PI / 180) * 640.0 / 360.0;  // at 1 m, fov_y 60
    const double x = (1 + 60.0 / 640.0) * halfWidth * 20;                  // 30 px outside
    SceneLight lamp;
    lamp.type = LightType::Point;
    lamp.position = {x, 0, -20};
    lamp.radius = 0.3;
    lamp.intensity = 2000;
    scene.lights = {lamp};
    scene.boxes.push_back({{x * 0.6 - 2, -3, -12}, {x * 0.6, 3, -11.9}});  // ends mid-light
    const VisibilityResult rays = truth(scene);
    ASSERT_GT(rays.lights[0].coverage, 0.2);
    ASSERT_LT(rays.lights[0].coverage, 0.8);
    ASSERT_EQ(rays.lights[0].inFrame, 0.0);

    const int band = 64;
    const DepthTarget target =
        makeDepthTarget(640 + 2 * band, 360 + 2 * band, 4, GL_DEPTH_COMPONENT32F);
    const fk_frame view =
        frameFor(scene, target, {band, band, 640, 360}, FK_DEPTH_MINUS_ONE_TO_ONE);
    fk_frame whole = view;
    whole.viewport[0] = whole.viewport[1] = 0;
    whole.viewport[2] = target.width, whole.viewport[3] = target.height;
    for (int c = 0; c < 4; ++c) {
        whole.projection[c * 4 + 0] *= 640.f / float(target.width);
        whole.projection[c * 4 + 1] *= 360.f / float(target.height);
    }
    DepthPass(scene).draw(target, whole);

    EnginePtr e = makeEngine(1);
    TempPreset streak;
    const int preset = fk_engine_load_preset(e.get(), streak.path.c_str());
    ASSERT_GE(preset, 0) << fk_error(e.get());
    const std::vector<fk_light> light = engineLights(scene, preset);
    float coverage = -1, inFrame = -1;
    ASSERT_EQ(fk_engine_occlusion(e.get(), &view, light.data(), 1), 0) << fk_error(e.get());
    ASSERT_EQ(fk_engine_read_view(e.get(), 0, &coverage, &inFrame, nullptr, 1), 1);
    EXPECT_EQ(coverage, 0.f);  // screen-only: nothing of it is in the frame
    ASSERT_EQ(fk_engine_set_guard_band(e.get(), 0, 1), 0);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &view, light.data(), 1), 0);
    ASSERT_EQ(fk_engine_read_view(e.get(), 0, &coverage, &inFrame, nullptr, 1), 1);
    EXPECT_NEAR(coverage, rays.lights[0].coverage, kTolerance);
    EXPECT_EQ(inFrame, 0.f);

    // The edge streak, drawn by the engine and by renderFlare with the same coverage.
    ASSERT_EQ(fk_engine_reset(e.get()), 0);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &view, light.data(), 1), 0);
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, target.width, target.height);
    auto fb = gl::makeFramebuffer(color.get());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    ASSERT_EQ(fk_engine_draw(e.get(), &view, light.data(), 1, fb->get()), 0) << fk_error(e.get());
    auto gpu = gl::readTextureRgba(color.get(), target.width, target.height);
    ASSERT_TRUE(gpu.ok());
    double inside = 0, elsewhere = 0;
    for (int y = band; y < band + 360; ++y)
        for (int px = band; px < band + 640; ++px)
            (px >= band + 640 - 100 ? inside : elsewhere) += gpu->at(px, y).r;
    EXPECT_GT(inside, 0.0);
    EXPECT_EQ(elsewhere, 0.0);  // only along the right edge (the streak is 90 px thick)

    auto presetData = loadPreset(streak.path);
    ASSERT_TRUE(presetData.ok());
    Image cpu(640, 360);
    Point at;
    ASSERT_TRUE(projectPoint(scene, lamp.position, at));
    const double tanRadius = 0.3 / std::sqrt(std::pow(length(lamp.position), 2) - 0.09);
    const double radiusOfHeight = tanRadius / (2 * std::tan(30.0 * M_PI / 180));
    const double flux = 2000 * M_PI * radiusOfHeight * radiusOfHeight;  // white: luminance 2000
    renderFlare(cpu, *presetData, at, float(coverage * flux));
    double cpuSum = 0;
    for (int y = 0; y < 360; ++y)
        for (int px = 0; px < 640; ++px) cpuSum += cpu.at(px, y).r;
    EXPECT_NEAR(inside / cpuSum, 1.0, 0.03);
}
