// SPDX-License-Identifier: Apache-2.0
// The engine API's batched occlusion on depth buffers rendered the way applications render
// them, against the ray-cast truth (every light's coverage within 0.02): flarekit's renderer
// with MSAA and translucent cards, each depth convention and format, point lights before and
// behind a wall, sub-viewports, and side-by-side stereo (each eye its coverage and flares).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

TEST(Engine, TwoHundredFiftySixLampsMatchTheRayCasterThroughFlarekitsRenderer) {
    EnginePtr e = makeEngine(256);
    const Scene scene = lampScene(256, 7);
    RenderOptions options;
    options.msaaSamples = 4;
    options.shadows = false;
    auto renderer = SceneRenderer::create(scene, options);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    ASSERT_TRUE(renderer->draw(scene).ok());
    const SceneTargets targets = sceneTargets(*renderer);
    ASSERT_NE(targets.transmittance, 0u);
    const fk_frame frame = engineFrame(scene, *renderer);
    ASSERT_EQ(fk_engine_set_transmittance(e.get(), 0, targets.transmittance), 0)
        << fk_error(e.get());
    const std::vector<fk_light> lights = engineLights(scene, -1);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 256), 0) << fk_error(e.get());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    int partial = 0;
    const double worst = worstError(readCoverage(e.get(), 256), truth(scene), &partial);
    EXPECT_LE(worst, kTolerance);
    EXPECT_GE(partial, 25);  // the scene really has partly hidden and translucent-covered lights
}

TEST(Engine, EveryDepthConventionAndFormatGivesTheRayCastCoverage) {
    const Scene scene = lampScene(64, 11, false);
    const VisibilityResult rays = truth(scene);
    EnginePtr e = makeEngine(64);
    const DepthPass pass(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    for (fk_depth_convention c :
         {FK_DEPTH_MINUS_ONE_TO_ONE, FK_DEPTH_ZERO_TO_ONE, FK_DEPTH_REVERSED_Z}) {
        for (GLenum format : {GLenum(GL_DEPTH_COMPONENT32F), GLenum(GL_DEPTH24_STENCIL8)}) {
            const DepthTarget target = makeDepthTarget(scene.width, scene.height, 4, format);
            const fk_frame frame = frameFor(scene, target, {0, 0, scene.width, scene.height}, c);
            pass.draw(target, frame);
            ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 64), 0)
                << fk_error(e.get());
            int partial = 0;
            EXPECT_LE(worstError(readCoverage(e.get(), 64), rays, &partial), kTolerance)
                << "convention " << c << ", format " << format;
            EXPECT_GE(partial, 5);
        }
    }
}

TEST(Engine, PointLightsInFrontOfAndBehindAWallUnderEachConvention) {
    const Scene scene = wallScene();
    EnginePtr e = makeEngine(4);
    const DepthPass pass(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    for (fk_depth_convention c :
         {FK_DEPTH_MINUS_ONE_TO_ONE, FK_DEPTH_ZERO_TO_ONE, FK_DEPTH_REVERSED_Z}) {
        const DepthTarget target =
            makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
        const fk_frame frame = frameFor(scene, target, {0, 0, scene.width, scene.height}, c);
        pass.draw(target, frame);
        ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 4), 0) << fk_error(e.get());
        const std::vector<float> cov = readCoverage(e.get(), 4);
        EXPECT_EQ(cov[0], 1.f) << "convention " << c;
        EXPECT_EQ(cov[1], 0.f) << "convention " << c;
        EXPECT_EQ(cov[2], 0.f) << "convention " << c;
        EXPECT_EQ(cov[3], 1.f) << "convention " << c;
    }
}

TEST(Engine, AViewportInsideALargerTextureMeasuresTheSame) {
    const Scene scene = lampScene(48, 3, false);
    EnginePtr e = makeEngine(48);
    const DepthPass pass(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    const DepthTarget full = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame fullFrame =
        frameFor(scene, full, {0, 0, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    pass.draw(full, fullFrame);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &fullFrame, lights.data(), 48), 0);
    const std::vector<float> alone = readCoverage(e.get(), 48);
    const DepthTarget big = makeDepthTarget(1500, 900, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame inside =
        frameFor(scene, big, {130, 90, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    pass.draw(big, inside);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &inside, lights.data(), 48), 0) << fk_error(e.get());
    const std::vector<float> offset = readCoverage(e.get(), 48);
    for (int i = 0; i < 48; ++i)
        EXPECT_NEAR(offset[std::size_t(i)], alone[std::size_t(i)], 0.002) << i;
    int partial = 0;
    EXPECT_LE(worstError(offset, truth(scene), &partial), 0.04);  // single-sample depth
}

namespace {
Scene eye(const Scene& s, double offset) {
    Scene e = s;
    const CameraBasis b = cameraBasis(s.camera);
    e.camera.position = s.camera.position + b.right * offset;
    e.camera.lookAt = s.camera.lookAt + b.right * offset;
    return e;
}
}  // namespace

namespace {
//! The two eyes' frames of a side-by-side stereo texture: the left half, then the right.
std::array<fk_frame, 2> sideBySide(const Scene& left, const Scene& right, const DepthTarget& t) {
    const int w = t.width / 2;
    return {frameFor(left, t, {0, 0, w, t.height}, FK_DEPTH_MINUS_ONE_TO_ONE),
            frameFor(right, t, {w, 0, w, t.height}, FK_DEPTH_MINUS_ONE_TO_ONE)};
}
}  // namespace

TEST(Engine, StereoGivesEachEyeItsOwnCoverageAndFlarePosition) {
    // Side by side in one 2:1 texture, as many VR runtimes hand it over; eyes 6.4 cm apart.
    const Scene centre = lampScene(32, 5, false);
    const Scene left = eye(centre, -0.032), right = eye(centre, 0.032);
    EnginePtr e = makeEngine(32);
    const DepthTarget both =
        makeDepthTarget(2 * centre.width, centre.height, 4, GL_DEPTH_COMPONENT32F);
    const std::array<fk_frame, 2> frames = sideBySide(left, right, both);
    DepthPass(left).draw(both, frames[0]);
    // The second eye must not clear the first: draw it through its own pass into a copy.
    const DepthTarget rightOnly =
        makeDepthTarget(2 * centre.width, centre.height, 4, GL_DEPTH_COMPONENT32F);
    DepthPass(right).draw(rightOnly, frames[1]);
    glBlitNamedFramebuffer(rightOnly.framebuffer.get(), both.framebuffer.get(), centre.width, 0,
                           2 * centre.width, centre.height, centre.width, 0, 2 * centre.width,
                           centre.height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    const std::vector<fk_light> lights = engineLights(centre, -1);
    ASSERT_EQ(fk_engine_occlusion_views(e.get(), frames.data(), 2, lights.data(), 32), 0)
        << fk_error(e.get());
    std::vector<float> views[2];
    for (int v = 0; v < 2; ++v) {
        views[v].assign(32, -1.f);
        ASSERT_EQ(fk_engine_read_view(e.get(), v, views[v].data(), nullptr, nullptr, 32), 32);
    }
    int partial = 0;
    EXPECT_LE(worstError(views[0], truth(left), &partial), kTolerance);
    EXPECT_LE(worstError(views[1], truth(right), &partial), kTolerance);
    EXPECT_EQ(views[0], readCoverage(e.get(), 32));  // read_coverage is view 0

    // One light, drawn per eye: each eye's glow peaks where that eye sees the light.
    Scene lamp = centre;
    lamp.lights = {centre.lights[0]};
    lamp.lights[0].position = centre.camera.position + Vec3{0.3, 0.2, -6};
    const Scene lampLeft = eye(lamp, -0.032), lampRight = eye(lamp, 0.032);
    const int preset = fk_engine_load_preset(e.get(), "subtle");
    ASSERT_GE(preset, 0) << fk_error(e.get());
    const std::vector<fk_light> one = engineLights(lamp, preset);
    const DepthTarget sky =
        makeDepthTarget(2 * centre.width, centre.height, 1, GL_DEPTH_COMPONENT32F);
    const std::array<fk_frame, 2> skyFrames = sideBySide(lampLeft, lampRight, sky);
    const float clearDepth = 1.f;
    glClearTexImage(sky.depth.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &clearDepth);
    ASSERT_EQ(fk_engine_occlusion_views(e.get(), skyFrames.data(), 2, one.data(), 1), 0)
        << fk_error(e.get());
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, 2 * centre.width, centre.height);
    auto fb = gl::makeFramebuffer(color.get());
    ASSERT_TRUE(fb.ok());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    for (int v = 0; v < 2; ++v)
        ASSERT_EQ(
            fk_engine_draw_view(e.get(), v, &skyFrames[std::size_t(v)], one.data(), 1, fb->get()),
            0)
            << fk_error(e.get());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    auto image = gl::readTextureRgba(color.get(), 2 * centre.width, centre.height);
    ASSERT_TRUE(image.ok());
    for (int v = 0; v < 2; ++v) {
        const Scene& eyeScene = v == 0 ? lampLeft : lampRight;
        Point expected;
        ASSERT_TRUE(projectPoint(eyeScene, lamp.lights[0].position, expected));
        float best = -1;
        int bx = 0, by = 0;
        for (int y = 0; y < centre.height; ++y)
            for (int x = 0; x < centre.width; ++x) {
                const float g = image->at(v * centre.width + x, y).g;
                if (g > best) best = g, bx = x, by = y;
            }
        EXPECT_GT(best, 0.f);
        EXPECT_NEAR(bx + 0.5, expected.x, 1.5) << "eye " << v;
        EXPECT_NEAR(by + 0.5, expected.y, 1.5) << "eye " << v;
    }
}
