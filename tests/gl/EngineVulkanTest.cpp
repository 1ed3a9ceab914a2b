// SPDX-License-Identifier: Apache-2.0
// The engine API's Vulkan backend on Mesa's lavapipe with the Khronos validation layer on:
// the same scenes measured and drawn by both backends (coverage within 0.005 of the GL
// backend's, and within 0.02 of the ray caster; the flare image within one 8-bit level), the
// frame-slot contract over many frames, and bad arguments refused by name. Every test ends
// with the validation layer silent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>

#include "DepthPass.h"
#include "EngineTesting.h"
#include "LightScenes.h"
#include "engine/vulkan/VulkanHost.h"
#include "engine/vulkan/VulkanRun.h"
#include "flarekit/Temporal.h"
#include "flarekit/flarekit_vulkan.h"
#include "gl/GlObjects.h"
#include "scene/SceneMesh.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

//! One host per test binary: creating a validated instance costs about a second on lavapipe.
vk::VulkanHost& host() {
    static std::unique_ptr<vk::VulkanHost> h = [] {
        auto made = vk::VulkanHost::create(true);
        EXPECT_TRUE(made.ok()) << made.error().message;
        return made.ok() ? std::move(*made) : nullptr;
    }();
    return *h;
}

EnginePtr makeVulkanEngine(int maxLights, int framesInFlight = 2) {
    const fk_vulkan_device d = host().engineDevice(framesInFlight);
    EnginePtr e(fk_engine_create_vulkan(&d, maxLights));
    EXPECT_TRUE(e) << fk_error(nullptr);
    return e;
}

//! The scene's opaque triangles as xyz floats.
std::vector<float> opaqueMesh(const Scene& scene) {
    std::vector<float> xyz;
    for (const MeshVertex& v : buildSceneMesh(opaqueObjects(scene)))
        xyz.insert(xyz.end(), v.position, v.position + 3);
    return xyz;
}

//! A frame as a Vulkan application has it: the same camera, its projection's y flipped (Vulkan
//! clip space points y down), the viewport measured from the top.
fk_frame vulkanFrame(const Scene& scene, fk_depth_convention convention) {
    fk_frame f = frameFor(scene, DepthTarget{}, {0, 0, scene.width, scene.height}, convention);
    f.width = scene.width, f.height = scene.height;
    for (int c = 0; c < 4; ++c) f.projection[4 * c + 1] = -f.projection[4 * c + 1];
    return f;
}

//! The depth of `scene` drawn by the host, and what an fk_vulkan_frame says of it.
struct VulkanDepth {
    vk::DepthImage image;
    fk_vulkan_frame frame{};
    ~VulkanDepth() { host().destroy(image); }
};

std::unique_ptr<VulkanDepth> drawVulkanDepth(const Scene& scene, const fk_frame& f, int samples,
                                             VkFormat format = VK_FORMAT_D32_SFLOAT) {
    auto d = std::make_unique<VulkanDepth>();
    auto image = host().depthImage(scene.width, scene.height, samples, format);
    EXPECT_TRUE(image.ok()) << image.error().message;
    if (!image.ok()) return d;
    d->image = *image;
    const auto vp = vk::viewProjection(f);
    const Status drawn =
        host().drawDepth(d->image, opaqueMesh(scene), vp.data(), f.depth_convention);
    EXPECT_TRUE(drawn.ok()) << drawn.error().message;
    d->frame.depth_view = d->image.view;
    d->frame.depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    d->frame.depth_samples = VkSampleCountFlagBits(samples);
    return d;
}

//! Records the occlusion of `lights` into one command buffer of frame `index` and waits.
void measure(fk_engine* e, fk_vulkan_frame vf, std::uint64_t index, const fk_frame& f,
             const std::vector<fk_light>& lights) {
    int rc = 0;
    ASSERT_TRUE(host()
                    .submit([&](VkCommandBuffer cmd) {
                        vf.command_buffer = cmd;
                        vf.frame_index = index;
                        rc = fk_engine_record_occlusion(e, &vf, &f, lights.data(),
                                                        int(lights.size()));
                    })
                    .ok());
    ASSERT_EQ(rc, 0) << fk_error(e);
}

void expectSilentValidation() {
    EXPECT_EQ(host().validationMessages(), 0) << host().firstValidationMessage();
}

int level(float v) {
    const double x = std::max(0.0, double(v));
    return int(std::lround(255.0 * x / (1.0 + x)));
}

}  // namespace

TEST(EngineVulkan, CoverageMatchesTheGlBackendAndTheRayCasterUnderEachConventionAndMsaa) {
    const Scene scene = lampScene(256, 7, false);
    const VisibilityResult rays = truth(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    EnginePtr gl = makeEngine(256);
    EnginePtr vkEngine = makeVulkanEngine(256);
    ASSERT_TRUE(vkEngine);
    const DepthPass pass(scene);
    std::uint64_t frameIndex = 0;
    for (int samples : {1, 4}) {
        for (fk_depth_convention c :  // [-1, 1] through VK_EXT_depth_clip_control
             {FK_DEPTH_MINUS_ONE_TO_ONE, FK_DEPTH_ZERO_TO_ONE, FK_DEPTH_REVERSED_Z}) {
            const DepthTarget target =
                makeDepthTarget(scene.width, scene.height, samples, GL_DEPTH_COMPONENT32F);
            const fk_frame glFrame = frameFor(scene, target, {0, 0, scene.width, scene.height}, c);
            pass.draw(target, glFrame);
            ASSERT_EQ(fk_engine_occlusion(gl.get(), &glFrame, lights.data(), 256), 0);
            const std::vector<float> glCoverage = readCoverage(gl.get(), 256);

            // The GL frame's own projection (clip y up): the Vulkan depth pass then writes the
            // same memory image with the same samples, and the coverage is the GL backend's.
            fk_frame same = vulkanFrame(scene, c);
            for (int k = 0; k < 4; ++k) same.projection[4 * k + 1] = -same.projection[4 * k + 1];
            auto depth = drawVulkanDepth(scene, same, samples);
            measure(vkEngine.get(), depth->frame, frameIndex++, same, lights);
            std::vector<float> vkCoverage = readCoverage(vkEngine.get(), 256);
            double apart = 0;
            for (int i = 0; i < 256; ++i)
                apart = std::max(apart, double(std::abs(vkCoverage[std::size_t(i)] -
                                                        glCoverage[std::size_t(i)])));
            EXPECT_LE(apart, 0.005) << "msaa " << samples << ", convention " << c;
            // A Vulkan application's projection (clip y down): at 4x the samples sit mirrored
            // against the geometry (Vulkan's standard positions are measured from the pixel's
            // top), a different rasterization of the same scene, held to the ray caster.
            const fk_frame f = vulkanFrame(scene, c);
            depth = drawVulkanDepth(scene, f, samples);
            measure(vkEngine.get(), depth->frame, frameIndex++, f, lights);
            vkCoverage = readCoverage(vkEngine.get(), 256);
            int partial = 0;
            // 1x depth cannot resolve the smallest lamps (docs/engine-api.md, "Small lights").
            EXPECT_LE(worstError(vkCoverage, rays, &partial), samples == 4 ? 0.025 : 0.1)
                << "msaa " << samples << ", convention " << c;
            EXPECT_GE(partial, 25);
        }
    }
    expectSilentValidation();
}

TEST(EngineVulkan, FlaresMatchTheGlBackendsWithinOneLevel) {
    const Scene scene = lampScene(64, 13, false, 960, 540);
    const char* edge =
        R"({"elements": [{"type": "edge-streak", "size": 0.2, "aspect": 6, "reach": 0.6,)"
        R"( "intensity": 0.8}, {"type": "ring", "t": -0.6, "size": 0.08, "intensity": 0.5}]})";
    std::vector<fk_light> lights = engineLights(scene, 0);
    for (std::size_t i = 0; i < lights.size(); i += 3) lights[i].preset = 1;
    lights[5].preset = -1;
    // GL: the engine's occlusion and draw into an RGBA32F target.
    EnginePtr gl = makeEngine(64);
    ASSERT_EQ(fk_engine_load_preset(gl.get(), "subtle"), 0);
    ASSERT_EQ(fk_engine_load_preset_json(gl.get(), edge, std::strlen(edge)), 1);
    const DepthPass pass(scene);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame glFrame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    pass.draw(target, glFrame);
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, scene.width, scene.height);
    auto fb = gl::makeFramebuffer(color.get());
    ASSERT_TRUE(fb.ok());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    ASSERT_EQ(fk_engine_occlusion(gl.get(), &glFrame, lights.data(), 64), 0);
    ASSERT_EQ(fk_engine_draw(gl.get(), &glFrame, lights.data(), 64, fb->get()), 0);
    std::vector<float> glPixels(std::size_t(scene.width) * scene.height * 4);
    glGetTextureImage(color.get(), 0, GL_RGBA, GL_FLOAT, GLsizei(glPixels.size() * sizeof(float)),
                      glPixels.data());

    // Vulkan: the same lights, occlusion and draw recorded into one command buffer.
    EnginePtr v = makeVulkanEngine(64);
    ASSERT_TRUE(v);
    ASSERT_EQ(fk_engine_load_preset(v.get(), "subtle"), 0) << fk_error(v.get());
    ASSERT_EQ(fk_engine_load_preset_json(v.get(), edge, std::strlen(edge)), 1);
    const fk_frame f = vulkanFrame(scene, FK_DEPTH_ZERO_TO_ONE);
    auto depth = drawVulkanDepth(scene, f, 1);
    auto image =
        host().colorImage(VK_FORMAT_R32G32B32A32_SFLOAT, scene.width, scene.height, nullptr);
    ASSERT_TRUE(image.ok()) << image.error().message;
    fk_vulkan_frame vf = depth->frame;
    vf.color_view = image->view;
    vf.color_format = VK_FORMAT_R32G32B32A32_SFLOAT;
    vf.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    int occluded = -9, drawn = -9;
    ASSERT_TRUE(host()
                    .submit([&](VkCommandBuffer cmd) {
                        vf.command_buffer = cmd;
                        occluded = fk_engine_record_occlusion(v.get(), &vf, &f, lights.data(), 64);
                        drawn = fk_engine_record_draw(v.get(), &vf, &f, lights.data(), 64);
                    })
                    .ok());
    ASSERT_EQ(occluded, 0) << fk_error(v.get());
    ASSERT_EQ(drawn, 0) << fk_error(v.get());
    auto vkPixels = host().readColor(*image, scene.width, scene.height);
    ASSERT_TRUE(vkPixels.ok());
    // Vulkan's rows run from the top, GL's from the bottom: row y of one is row h - 1 - y.
    int worst = 0;
    double lit = 0;
    const std::size_t rowFloats = std::size_t(scene.width) * 4;
    for (int y = 0; y < scene.height; ++y) {
        const float* a = glPixels.data() + std::size_t(y) * rowFloats;
        const float* b = vkPixels->data() + std::size_t(scene.height - 1 - y) * rowFloats;
        for (std::size_t i = 0; i < rowFloats; ++i) {
            if (i % 4 == 3) continue;
            worst = std::max(worst, std::abs(level(a[i]) - level(b[i])));
            lit += level(a[i]) > 2 ? 1 : 0;
        }
    }
    EXPECT_LE(worst, 1);
    EXPECT_GT(lit, 0.05 * scene.width * scene.height);
    vk::Image owned = *image;
    host().device().destroy(owned);
    expectSilentValidation();
}

TEST(EngineVulkan, FramesInFlightReuseTheirSlotsAndTheFilterRunsAcrossFrames) {
    // 40 frames of a light behind a wall, then in the open, over two frames in flight: the
    // slots' descriptor sets recycle (the pool holds 32 a frame) and the filter steps as the
    // CPU filter does.
    Scene scene = wallScene();
    Scene open = scene;
    open.boxes.clear();
    const std::vector<fk_light> lights = engineLights(scene, -1);
    EnginePtr v = makeVulkanEngine(4, 2);
    ASSERT_TRUE(v);
    const fk_frame f = vulkanFrame(scene, FK_DEPTH_ZERO_TO_ONE);
    auto walled = drawVulkanDepth(scene, f, 1);
    auto clear = drawVulkanDepth(open, f, 1);
    TemporalFilter cpu;
    for (std::uint64_t frame = 0; frame < 40; ++frame) {
        const bool wall = frame < 20;
        measure(v.get(), (wall ? walled : clear)->frame, frame, f, lights);
        float raw = 0, filtered = 0;
        ASSERT_EQ(fk_engine_read_view(v.get(), 0, &raw, nullptr, &filtered, 1), 1);
        EXPECT_EQ(raw, 1.f) << frame;  // light 0 sits in front of the wall
        EXPECT_EQ(filtered, 1.f) << frame;
        std::vector<float> r(4), fl(4);
        ASSERT_EQ(fk_engine_read_view(v.get(), 0, r.data(), nullptr, fl.data(), 4), 4);
        const float raw1 = r[2], filtered1 = fl[2];  // straight into the wall, then open sky
        EXPECT_EQ(raw1, wall ? 0.f : 1.f) << frame;
        const TemporalState st = cpu.update(raw1, {160, 90}, true, 320, 180, f.dt_seconds);
        EXPECT_NEAR(filtered1, st.coverage, 1e-5) << frame;
    }
    expectSilentValidation();
}

TEST(EngineVulkan, BadArgumentsAreRefusedByNameAndGlCallsToo) {
    EXPECT_EQ(fk_engine_create_vulkan(nullptr, 4), nullptr);
    EXPECT_NE(std::string(fk_error(nullptr)).find("device: expected"), std::string::npos);
    fk_vulkan_device d = host().engineDevice(0);
    EXPECT_EQ(fk_engine_create_vulkan(&d, 4), nullptr);
    EXPECT_NE(std::string(fk_error(nullptr)).find("frames_in_flight: expected 1..8"),
              std::string::npos);
    d = host().engineDevice(2);
    EXPECT_EQ(fk_engine_create_vulkan(&d, 0), nullptr);
    EXPECT_NE(std::string(fk_error(nullptr)).find("max_lights"), std::string::npos);

    EnginePtr v = makeVulkanEngine(4);
    ASSERT_TRUE(v);
    const Scene scene = wallScene();
    const std::vector<fk_light> lights = engineLights(scene, -1);
    const fk_frame f = vulkanFrame(scene, FK_DEPTH_ZERO_TO_ONE);
    const auto error = [&] { return std::string(fk_error(v.get())); };
    EXPECT_LT(fk_engine_occlusion(v.get(), &f, lights.data(), 4), 0);
    EXPECT_NE(error().find("this engine is a Vulkan engine"), std::string::npos) << error();
    EXPECT_LT(fk_engine_draw(v.get(), &f, lights.data(), 4, 0), 0);
    EXPECT_EQ(fk_engine_coverage_texture(v.get()), 0u);
    EXPECT_NE(fk_engine_coverage_view(v.get()), VkImageView(VK_NULL_HANDLE));
    EnginePtr gl = makeEngine(4);
    fk_vulkan_frame vf{};
    EXPECT_LT(fk_engine_record_occlusion(gl.get(), &vf, &f, lights.data(), 4), 0);
    EXPECT_NE(std::string(fk_error(gl.get())).find("OpenGL engine"), std::string::npos);

    auto depth = drawVulkanDepth(scene, f, 1);
    struct Case {
        std::function<void(fk_vulkan_frame&, fk_frame&)> spoil;
        std::string message;
    };
    for (const Case& c : std::vector<Case>{
             {[](fk_vulkan_frame&x, fk_frame&) { x.depth_view = VK_NULL_HANDLE; },
              "vulkan frame.depth_view"},
             {[](fk_vulkan_frame&x, fk_frame&) {
                  x.depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
              },
              "vulkan frame.depth_layout: expected"},
             {[](fk_vulkan_frame&x, fk_frame&) { x.depth_samples = VkSampleCountFlagBits(3); },
              "vulkan frame.depth_samples: expected 1, 2, 4, 8 or 16, got 3"},
             {[](fk_vulkan_frame&, fk_frame&y) { y.viewport[2] = 0; }, "frame.viewport"},
             {[](fk_vulkan_frame&, fk_frame&y) { y.view[3] = NAN; }, "frame.view"},
         }) {
        fk_vulkan_frame x = depth->frame;
        fk_frame y = f;
        c.spoil(x, y);
        int rc = 0;
        ASSERT_TRUE(host()
                        .submit([&](VkCommandBuffer cmd) {
                            x.command_buffer = cmd;
                            rc = fk_engine_record_occlusion(v.get(), &x, &y, lights.data(), 4);
                        })
                        .ok());
        EXPECT_LT(rc, 0) << c.message;
        EXPECT_NE(error().find(c.message), std::string::npos) << error();
    }
    fk_vulkan_frame noCommands = depth->frame;
    EXPECT_LT(fk_engine_record_occlusion(v.get(), &noCommands, &f, lights.data(), 4), 0);
    EXPECT_NE(error().find("command_buffer"), std::string::npos);
    fk_vulkan_frame badColor = depth->frame;
    int rc = 0;
    ASSERT_TRUE(host()
                    .submit([&](VkCommandBuffer cmd) {
                        badColor.command_buffer = cmd;
                        rc = fk_engine_record_draw(v.get(), &badColor, &f, lights.data(), 4);
                    })
                    .ok());
    EXPECT_LT(rc, 0);
    EXPECT_NE(error().find("vulkan frame.color_view"), std::string::npos) << error();
    expectSilentValidation();
}

TEST(EngineVulkan, SmallLightsAreMeasuredFromSunMapsTheOccluderCallbackDraws) {
    // 256 lamps of 0.5-40 px radius under both [0, 1] conventions at 1x and 4x MSAA: with the
    // occluder callback, the small ones from sun maps, every lamp within 0.02 of the ray caster.
    const Scene scene = lampScene(256, 31, false, 1280, 720, {0.5, 40});
    const VisibilityResult rays = truth(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    EnginePtr v = makeVulkanEngine(256);
    ASSERT_TRUE(v);
    auto occluders = vk::VulkanOccluders::create(host(), scene);
    ASSERT_TRUE(occluders.ok()) << occluders.error().message;
    std::uint64_t frameIndex = 0;
    for (int samples : {1, 4}) {
        for (fk_depth_convention c : {FK_DEPTH_ZERO_TO_ONE, FK_DEPTH_REVERSED_Z}) {
            const fk_frame f = vulkanFrame(scene, c);
            auto depth = drawVulkanDepth(scene, f, samples);
            ASSERT_EQ(fk_engine_set_vulkan_occluder_callback(v.get(), nullptr, nullptr), 0);
            measure(v.get(), depth->frame, frameIndex++, f, lights);
            int partial = 0;
            const double depthOnly = worstError(readCoverage(v.get(), 256), rays, &partial);
            EXPECT_GT(depthOnly, 0.03);  // the depth's sample grid shows on the smallest lamps
            (*occluders)->calls = 0;
            ASSERT_EQ(fk_engine_set_vulkan_occluder_callback(v.get(), &vk::VulkanOccluders::draw,
                                                             occluders->get()),
                      0);
            measure(v.get(), depth->frame, frameIndex++, f, lights);
            EXPECT_LE(worstError(readCoverage(v.get(), 256), rays, &partial), kTolerance)
                << "msaa " << samples << ", convention " << c;
            EXPECT_GE(partial, 25);
            EXPECT_GT((*occluders)->calls, 40);  // the small lamps, and only they
            EXPECT_LT((*occluders)->calls, 216);
        }
    }
    expectSilentValidation();
}

TEST(EngineVulkan, SunMapsSeeTranslucentCardsThroughTheCallback) {
    // Every lamp tiled (the threshold past any lamp's footprint): texture masking on Vulkan,
    // glass and fog cards multiplying the tiles, against the ray caster.
    const Scene scene = lampScene(128, 5, true, 960, 540, {1, 30});
    const VisibilityResult rays = truth(scene);
    const std::vector<fk_light> lights = engineLights(scene, -1);
    EnginePtr v = makeVulkanEngine(128);
    ASSERT_TRUE(v);
    auto occluders = vk::VulkanOccluders::create(host(), scene);
    ASSERT_TRUE(occluders.ok()) << occluders.error().message;
    ASSERT_EQ(fk_engine_set_vulkan_occluder_callback(v.get(), &vk::VulkanOccluders::draw,
                                                     occluders->get()),
              0);
    ASSERT_EQ(fk_engine_set_tile_threshold(v.get(), 1 << 20), 0);
    EXPECT_LT(fk_engine_set_tile_threshold(v.get(), -1), 0);
    const fk_frame f = vulkanFrame(scene, FK_DEPTH_REVERSED_Z);
    auto depth = drawVulkanDepth(scene, f, 1);
    measure(v.get(), depth->frame, 0, f, lights);
    EXPECT_EQ((*occluders)->calls, 128);
    int partial = 0;
    EXPECT_LE(worstError(readCoverage(v.get(), 128), rays, &partial), kTolerance);
    EXPECT_GE(partial, 10);
    expectSilentValidation();
}
