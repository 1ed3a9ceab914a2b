// SPDX-License-Identifier: Apache-2.0
// Every light right at any size: 256 lamps from 0.5 px to 40 px radius among boxes and spheres
// (and translucent cards), under each depth convention at 1x and 4x MSAA, measured by the
// default method against the ray caster. With an occluder callback the lights a few pixels
// wide are measured from sun-map tiles and the rest from the frame's depth, in the same call;
// without one the depth's sample grid shows in the small lights, which the test shows too.
#include <gtest/gtest.h>

#include <cmath>

#include "DepthPass.h"
#include "EngineTesting.h"
#include "LightScenes.h"
#include "flarekit/Visibility.h"
#include "flarekit/flarekit.h"
#include "flarekit/gl/EngineScene.h"
#include "flarekit/gl/Render.h"
#include "scene/SceneTargets.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {
//! Lights off by more than the tolerance.
int lightsOff(const std::vector<float>& engine, const VisibilityResult& rays) {
    int off = 0;
    for (std::size_t i = 0; i < engine.size(); ++i)
        off += std::abs(double(engine[i]) - rays.lights[i].coverage) > kTolerance ? 1 : 0;
    return off;
}

//! Counts the occluder callback's calls, then draws as SceneOccluders does.
struct CountingOccluders {
    SceneOccluders* scene = nullptr;
    int calls = 0;
    static void draw(void* user, int view, int light, const float* vp, unsigned fb,
                     const int* viewport) {
        auto* self = static_cast<CountingOccluders*>(user);
        ++self->calls;
        SceneOccluders::draw(self->scene, view, light, vp, fb, viewport);
    }
};
}  // namespace

TEST(EngineSmallLights, EveryLightFromHalfAPixelToFortyUnderEachConventionAndMsaa) {
    const Scene scene = lampScene(256, 31, false, 1280, 720, {0.5, 40});
    const VisibilityResult rays = truth(scene);
    EnginePtr e = makeEngine(256);
    auto occluders = SceneOccluders::create(scene);
    ASSERT_TRUE(occluders.ok()) << occluders.error().message;
    CountingOccluders counting{occluders->get()};
    const DepthPass pass(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    for (int samples : {1, 4}) {
        for (fk_depth_convention c :
             {FK_DEPTH_MINUS_ONE_TO_ONE, FK_DEPTH_ZERO_TO_ONE, FK_DEPTH_REVERSED_Z}) {
            const DepthTarget target =
                makeDepthTarget(scene.width, scene.height, samples, GL_DEPTH_COMPONENT32F);
            const fk_frame frame = frameFor(scene, target, {0, 0, scene.width, scene.height}, c);
            pass.draw(target, frame);
            fk_engine_set_occluder_callback(e.get(), nullptr, nullptr);
            ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 256), 0)
                << fk_error(e.get());
            const int depthOnly = lightsOff(readCoverage(e.get(), 256), rays);
            EXPECT_GE(depthOnly, samples == 1 ? 3 : 1);  // the sample grid shows without tiles

            counting.calls = 0;
            fk_engine_set_occluder_callback(e.get(), &CountingOccluders::draw, &counting);
            const AppState before = readState();
            ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 256), 0)
                << fk_error(e.get());
            EXPECT_TRUE(readState() == before);
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
            const std::vector<float> coverage = readCoverage(e.get(), 256);
            int partial = 0;
            EXPECT_LE(worstError(coverage, rays, &partial), kTolerance)
                << "msaa " << samples << ", convention " << c;
            EXPECT_GE(partial, 25);
            // Only the small lights cost a callback: under 1,024 depth samples.
            int small = 0;
            const double focal = 0.5 * scene.height / std::tan(scene.camera.fovYDeg * M_PI / 360);
            for (const SceneLight& l : scene.lights) {
                const double d = length(l.position - scene.camera.position);
                const double r = std::tan(std::asin(l.radius / d)) * focal;
                small += M_PI * r * r * samples < 1024 ? 1 : 0;
            }
            EXPECT_EQ(counting.calls, small);
            EXPECT_GT(small, 40);
            EXPECT_LT(small, 256 - 40);
        }
    }
    // A threshold of 0 measures every light on the depth, as without a callback.
    ASSERT_EQ(fk_engine_set_tile_threshold(e.get(), 0), 0);
    counting.calls = 0;
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    pass.draw(target, frame);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 256), 0);
    EXPECT_EQ(counting.calls, 0);
    EXPECT_LT(fk_engine_set_tile_threshold(e.get(), -1), 0);
    EXPECT_NE(std::string(fk_error(e.get())).find("tile-below: expected 0.."), std::string::npos);
}

TEST(EngineSmallLights, TranslucentCardsAndMultisampledSceneRendererFrames) {
    // The scene renderer's own frames (MSAA depth, transmittance target), small lights behind
    // glass and fog cards: tiles see the cards through the callback's grey, the depth pass
    // through the transmittance texture.
    const Scene scene = lampScene(256, 5, true, 1280, 720, {0.5, 40});
    const VisibilityResult rays = truth(scene);
    for (int msaa : {1, 4}) {
        EnginePtr e = makeEngine(256);
        RenderOptions options;
        options.msaaSamples = msaa;
        options.shadows = false;
        auto renderer = SceneRenderer::create(scene, options);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        ASSERT_TRUE(renderer->draw(scene).ok());
        auto occluders = SceneOccluders::create(scene);
        ASSERT_TRUE(occluders.ok());
        fk_engine_set_occluder_callback(e.get(), &SceneOccluders::draw, occluders->get());
        ASSERT_EQ(fk_engine_set_transmittance(e.get(), 0, sceneTargets(*renderer).transmittance),
                  0);
        const fk_frame frame = engineFrame(scene, *renderer);
        const std::vector<fk_light> lights = engineLights(scene, -1);
        ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 256), 0) << fk_error(e.get());
        int partial = 0;
        EXPECT_LE(worstError(readCoverage(e.get(), 256), rays, &partial), kTolerance)
            << "msaa " << msaa;
        EXPECT_GE(partial, 25);
    }
}
