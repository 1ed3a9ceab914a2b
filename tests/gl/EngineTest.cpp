// The engine API (flarekit.h) on depth buffers rendered the way applications render them,
// against the ray-cast truth (every light's coverage within 0.02), across depth conventions,
// MSAA, sub-viewports and stereo; its temporal filter against TemporalFilter; its flare draw
// against renderFlare; the GL state it must leave alone; and every bad argument.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>

#include <epoxy/egl.h>

#include "DepthPass.h"
#include "GlTestContext.h"
#include "LightScenes.h"
#include "flarekit/Flare.h"
#include "flarekit/Render.h"
#include "flarekit/SunFlare.h"
#include "flarekit/Temporal.h"
#include "flarekit/Visibility.h"
#include "flarekit/flarekit.h"
#include "flarekit/flarekit.hpp"
#include "scene/SceneTargets.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

// The API's accuracy bound against the ray caster (4x MSAA depth).
constexpr double kTolerance = 0.02;

struct EngineDeleter {
    void operator()(fk_engine* e) const { fk_engine_destroy(e); }
};
using EnginePtr = std::unique_ptr<fk_engine, EngineDeleter>;

EnginePtr makeEngine(int maxLights) {
    glContext();
    EnginePtr e(fk_engine_create(maxLights));
    EXPECT_TRUE(e) << fk_error(nullptr);
    return e;
}

std::vector<float> readCoverage(fk_engine* e, int count) {
    std::vector<float> c(std::size_t(count), -1.f);
    EXPECT_EQ(fk_engine_read_coverage(e, c.data(), count), count) << fk_error(e);
    return c;
}

VisibilityResult truth(const Scene& s) {
    RaycastOptions o;
    o.samplesPerSide = 64;  // 4,096 rays a light: error near 0.003, well inside 0.02
    auto r = raycastVisibility(s, o);
    EXPECT_TRUE(r.ok());
    return *r;
}

//! Worst |engine - raycast| over the lights, and how many lights were partly hidden.
double worstError(const std::vector<float>& engine, const VisibilityResult& rays, int* partial) {
    double worst = 0;
    *partial = 0;
    for (std::size_t i = 0; i < engine.size(); ++i) {
        worst = std::max(worst, std::abs(double(engine[i]) - rays.lights[i].coverage));
        if (rays.lights[i].coverage > 0.02 && rays.lights[i].coverage < 0.98) ++*partial;
    }
    return worst;
}

//! A preset file holding one edge streak, removed afterwards.
struct TempPreset {
    std::string path = std::filesystem::temp_directory_path() /
                       ("flarekit-edge-" + std::to_string(::getpid()) + ".json");
    TempPreset() {
        std::ofstream(path) << R"({"name": "edge", "elements": [{"type": "edge-streak", "size": )"
                               R"(0.25, "aspect": 8, "reach": 0.3, "intensity": 0.8}]})";
    }
    ~TempPreset() { std::filesystem::remove(path); }
};

}  // namespace

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

namespace {
Scene wallScene() {
    Scene s;
    s.width = 320, s.height = 180;
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, -1};
    s.camera.farPlane = 500;
    s.sun.intensity = 0;
    s.boxes.push_back({{-4, -4, -21}, {4, 4, -20}});
    SceneLight front, behind, ahead, aside;
    front.type = behind.type = LightType::Point;
    front.position = {0.5, 0.5, -10}, front.radius = 0.2;
    behind.position = {0.5, 0.5, -30}, behind.radius = 0.2;
    ahead.direction = {0, 0, -1};                       // straight into the wall
    aside.direction = normalize(Vec3{0.35, 0.15, -1});  // in frame, past the wall's edge
    s.lights = {front, behind, ahead, aside};
    return s;
}
}  // namespace

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

TEST(Engine, StereoGivesEachEyeItsOwnCoverageAndFlarePosition) {
    // Side by side in one 2:1 texture, as many VR runtimes hand it over; eyes 6.4 cm apart.
    const Scene centre = lampScene(32, 5, false);
    const Scene left = eye(centre, -0.032), right = eye(centre, 0.032);
    EnginePtr e = makeEngine(32);
    const DepthTarget both =
        makeDepthTarget(2 * centre.width, centre.height, 4, GL_DEPTH_COMPONENT32F);
    fk_frame frames[2] = {
        frameFor(left, both, {0, 0, centre.width, centre.height}, FK_DEPTH_MINUS_ONE_TO_ONE),
        frameFor(right, both, {centre.width, 0, centre.width, centre.height},
                 FK_DEPTH_MINUS_ONE_TO_ONE)};
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
    ASSERT_EQ(fk_engine_occlusion_views(e.get(), frames, 2, lights.data(), 32), 0)
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
    fk_frame skyFrames[2] = {
        frameFor(lampLeft, sky, {0, 0, centre.width, centre.height}, FK_DEPTH_MINUS_ONE_TO_ONE),
        frameFor(lampRight, sky, {centre.width, 0, centre.width, centre.height},
                 FK_DEPTH_MINUS_ONE_TO_ONE)};
    const float clearDepth = 1.f;
    glClearTexImage(sky.depth.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &clearDepth);
    ASSERT_EQ(fk_engine_occlusion_views(e.get(), skyFrames, 2, one.data(), 1), 0)
        << fk_error(e.get());
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, 2 * centre.width, centre.height);
    auto fb = gl::makeFramebuffer(color.get());
    ASSERT_TRUE(fb.ok());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    for (int v = 0; v < 2; ++v)
        ASSERT_EQ(fk_engine_draw_view(e.get(), v, &skyFrames[v], one.data(), 1, fb->get()), 0)
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

namespace {
//! Every piece of state GlStateGuard promises to keep, read back.
struct AppState {
    GLint program, vao, drawFb, readFb, viewport[4], active, image, ssbo6, ssbo7, ssboGeneric;
    GLint units[4][3];  // 2D, 2D multisample, sampler on units 12-15
    GLboolean blend0, blend1, depthTest, depthMask, scissor, cull, stencil, mask0[4], mask1[4];
    GLint src0, dst0, eq0, src1, polygon[2];
    bool operator==(const AppState&) const = default;
};

AppState readState() {
    AppState s{};
    glGetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vao);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.drawFb);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.readFb);
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &s.active);
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 7, &s.image);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 6, &s.ssbo6);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 7, &s.ssbo7);
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &s.ssboGeneric);
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < 4; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE12 + u));
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &s.units[u][0]);
        glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &s.units[u][1]);
        glGetIntegerv(GL_SAMPLER_BINDING, &s.units[u][2]);
    }
    glActiveTexture(GLenum(active));
    s.blend0 = glIsEnabledi(GL_BLEND, 0);
    s.blend1 = glIsEnabledi(GL_BLEND, 1);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, 0, &s.src0);
    glGetIntegeri_v(GL_BLEND_DST_RGB, 0, &s.dst0);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, 0, &s.eq0);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, 1, &s.src1);
    glGetBooleani_v(GL_COLOR_WRITEMASK, 0, s.mask0);
    glGetBooleani_v(GL_COLOR_WRITEMASK, 1, s.mask1);
    s.depthTest = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &s.depthMask);
    s.scissor = glIsEnabled(GL_SCISSOR_TEST);
    s.cull = glIsEnabled(GL_CULL_FACE);
    s.stencil = glIsEnabled(GL_STENCIL_TEST);
    glGetIntegerv(GL_POLYGON_MODE, s.polygon);
    return s;
}
}  // namespace

TEST(Engine, LeavesTheApplicationsGlStateAsItFoundIt) {
    const Scene scene = wallScene();
    EnginePtr e = makeEngine(4);
    const int preset = fk_engine_load_preset(e.get(), "subtle");
    std::vector<fk_light> lights = engineLights(scene, preset);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 4, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_MINUS_ONE_TO_ONE);
    DepthPass(scene).draw(target, frame);
    // An application mid-frame: its own program, VAO, framebuffer, textures, bindings, blend.
    gl::Texture appColor = gl::makeTexture2D(GL_RGBA16F, scene.width, scene.height);
    gl::Texture appTexture = gl::makeTexture2D(GL_RGBA8, 4, 4);
    auto appFb = gl::makeFramebuffer(appColor.get());
    auto appProgram =
        gl::linkProgram({{GL_VERTEX_SHADER, "app.vert",
                          "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n"},
                         {GL_FRAGMENT_SHADER, "app.frag",
                          "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n"}});
    ASSERT_TRUE(appFb.ok() && appProgram.ok());
    gl::VertexArray appVao = gl::makeVertexArray();
    GLuint appBuffer = 0, appSampler = 0;
    glCreateBuffers(1, &appBuffer);
    glNamedBufferData(appBuffer, 256, nullptr, GL_DYNAMIC_DRAW);
    glCreateSamplers(1, &appSampler);
    glUseProgram(appProgram->get());
    glBindVertexArray(appVao.get());
    glBindFramebuffer(GL_FRAMEBUFFER, appFb->get());
    glViewport(3, 5, 100, 50);
    for (GLuint u = 12; u < 16; ++u) {
        glBindTextureUnit(u, appTexture.get());
        glBindSampler(u, appSampler);
    }
    glActiveTexture(GL_TEXTURE3);
    glBindImageTexture(7, appTexture.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, appBuffer);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 7, appBuffer, 0, 128);
    glEnablei(GL_BLEND, 0);
    glDisablei(GL_BLEND, 1);
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    glBlendFuncSeparatei(1, GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ZERO);
    glBlendEquationSeparatei(0, GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_ADD);
    glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColorMaski(1, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_STENCIL_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    const AppState before = readState();

    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 4), 0) << fk_error(e.get());
    EXPECT_TRUE(readState() == before) << "after fk_engine_occlusion";
    ASSERT_EQ(fk_engine_draw(e.get(), &frame, lights.data(), 4, appFb->get()), 0)
        << fk_error(e.get());
    EXPECT_TRUE(readState() == before) << "after fk_engine_draw";
    float coverage[4];
    ASSERT_EQ(fk_engine_read_coverage(e.get(), coverage, 4), 4);
    EXPECT_TRUE(readState() == before) << "after fk_engine_read_coverage";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    // The flare was drawn despite the application's polygon mode, masks and scissor.
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    auto image = gl::readTextureRgba(appColor.get(), scene.width, scene.height);
    ASSERT_TRUE(image.ok());
    double sum = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) sum += image->at(x, y).r + image->at(x, y).g;
    EXPECT_GT(sum, 0.0);

    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (GLuint u = 12; u < 16; ++u) glBindSampler(u, 0);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_DEPTH_TEST), glDepthMask(GL_TRUE), glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE), glDisable(GL_STENCIL_TEST), glDisablei(GL_BLEND, 0);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glDeleteBuffers(1, &appBuffer);
    glDeleteSamplers(1, &appSampler);
}

TEST(Engine, BadArgumentsAreRefusedByNameWithNothingDrawnAndNoGlError) {
    EXPECT_EQ(fk_engine_create(0), nullptr);
    EXPECT_NE(std::string(fk_error(nullptr)).find("max_lights: expected 1..16384, got 0"),
              std::string::npos)
        << fk_error(nullptr);
    const Scene scene = wallScene();
    EnginePtr e = makeEngine(4);
    const int preset = fk_engine_load_preset(e.get(), "subtle");
    ASSERT_GE(preset, 0);
    const std::vector<fk_light> good = engineLights(scene, preset);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_MINUS_ONE_TO_ONE);
    DepthPass(scene).draw(target, frame);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, good.data(), 4), 0);
    const std::vector<float> measured = readCoverage(e.get(), 4);
    gl::Texture color = gl::makeTexture2D(GL_RGBA32F, scene.width, scene.height);
    gl::Texture notDepth = gl::makeTexture2D(GL_RGBA8, scene.width, scene.height);
    auto fb = gl::makeFramebuffer(color.get());
    const float black[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fb->get(), GL_COLOR, 0, black);
    const float nan = std::nanf(""), inf = INFINITY;

    struct Case {
        const char* what;
        std::function<int()> call;
        const char* message;
    };
    const auto withFrame = [&](auto change) {
        fk_frame f = frame;
        change(f);
        return f;
    };
    const auto withLight = [&](int i, auto change) {
        std::vector<fk_light> l = good;
        change(l[std::size_t(i)]);
        return l;
    };
    std::vector<Case> cases = {
        {"depth 0",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.depth_texture = 0; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "fk_engine_occlusion: frame.depth_texture: expected the name of a GL texture, got 0"},
        {"not a texture",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.depth_texture = 987654; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.depth_texture: expected the name of a GL texture, got 987654"},
        {"colour texture",
         [&] {
             auto f = withFrame([&](fk_frame& x) { x.depth_texture = notDepth.get(); });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.depth_texture: expected a depth format"},
        {"wrong size",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.width = 640; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.depth_texture: is 320 x 180; expected the frame's width x height, 640 x 180"},
        {"size mismatch",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.width = 640, x.height = 360; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.depth_texture: is 320 x 180; expected the frame's width x height, 640 x 360"},
        {"viewport out",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.viewport[0] = 10; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.viewport: expected x, y >= 0, w, h >= 1 inside the 320 x 180 depth texture, got "
         "[10, 0, 320, 180]"},
        {"nan view",
         [&] {
             auto f = withFrame([&](fk_frame& x) { x.view[5] = nan; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.view: expected 16 finite numbers"},
        {"inf projection",
         [&] {
             auto f = withFrame([&](fk_frame& x) { x.projection[0] = inf; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.projection: expected 16 finite numbers"},
        {"negative dt",
         [&] {
             auto f = withFrame([](fk_frame& x) { x.dt_seconds = -1; });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.dt_seconds: expected a finite number >= 0, got -1"},
        {"convention",
         [&] {
             auto f = withFrame([](fk_frame& x) {
                 const int seven = 7;
                 std::memcpy(&x.depth_convention, &seven, sizeof seven);
             });
             return fk_engine_occlusion(e.get(), &f, good.data(), 4);
         },
         "frame.depth_convention: expected 0, 1 or 2"},
        {"count", [&] { return fk_engine_occlusion(e.get(), &frame, good.data(), 5); },
         "count: expected 0..4 (the engine's max_lights), got 5"},
        {"null lights", [&] { return fk_engine_occlusion(e.get(), &frame, nullptr, 2); },
         "lights: expected an array, got NULL"},
        {"nan position",
         [&] {
             auto l = withLight(1, [&](fk_light& x) { x.position[2] = nan; });
             return fk_engine_occlusion(e.get(), &frame, l.data(), 4);
         },
         "lights[1].position: expected 3 finite numbers"},
        {"negative radius",
         [&] {
             auto l = withLight(0, [](fk_light& x) { x.radius = -0.5f; });
             return fk_engine_occlusion(e.get(), &frame, l.data(), 4);
         },
         "lights[0].radius: expected a positive number (world units), got -0.5"},
        {"zero direction",
         [&] {
             auto l = withLight(
                 2, [](fk_light& x) { x.direction[0] = x.direction[1] = x.direction[2] = 0; });
             return fk_engine_occlusion(e.get(), &frame, l.data(), 4);
         },
         "lights[2].direction: expected a non-zero direction"},
        {"huge angle",
         [&] {
             auto l = withLight(3, [](fk_light& x) { x.radius = 60; });
             return fk_engine_occlusion(e.get(), &frame, l.data(), 4);
         },
         "lights[3].radius: expected an angle in (0, 45] degrees, got 60"},
        {"type",
         [&] {
             auto l = withLight(0, [](fk_light& x) {
                 const int nine = 9;
                 std::memcpy(&x.type, &nine, sizeof nine);
             });
             return fk_engine_occlusion(e.get(), &frame, l.data(), 4);
         },
         "lights[0].type: expected FK_LIGHT_DIRECTIONAL (0) or FK_LIGHT_POINT (1), got 9"},
        {"preset id",
         [&] {
             auto l = withLight(0, [](fk_light& x) { x.preset = 3; });
             return fk_engine_draw(e.get(), &frame, l.data(), 4, fb->get());
         },
         "fk_engine_draw: lights[0].preset: expected -1 or an id from fk_engine_load_preset "
         "(0..0), got 3"},
        {"nan intensity",
         [&] {
             auto l = withLight(0, [&](fk_light& x) { x.intensity = nan; });
             return fk_engine_draw(e.get(), &frame, l.data(), 4, fb->get());
         },
         "lights[0].intensity: expected a finite number >= 0"},
        {"framebuffer", [&] { return fk_engine_draw(e.get(), &frame, good.data(), 4, 424242); },
         "fk_engine_draw: framebuffer: expected 0 or the name of a GL framebuffer, got 424242"},
        {"views", [&] { return fk_engine_occlusion_views(e.get(), &frame, 5, good.data(), 4); },
         "fk_engine_occlusion_views: views: expected 1..4, got 5"},
        {"null frame", [&] { return fk_engine_occlusion(e.get(), nullptr, good.data(), 4); },
         "fk_engine_occlusion: frame: expected a frame, got NULL"},
        {"method", [&] { return fk_engine_set_method(e.get(), "pbo"); },
         "fk_engine_set_method: method: expected \"compute\""},
        {"preset name", [&] { return fk_engine_load_preset(e.get(), "no-such-preset"); },
         "fk_engine_load_preset: "},
        {"samples", [&] { return fk_engine_set_samples(e.get(), 0); },
         "fk_engine_set_samples: samples_per_side: expected 1..64, got 0"},
        {"transmittance", [&] { return fk_engine_set_transmittance(e.get(), 0, 31337); },
         "fk_engine_set_transmittance: texture: expected 0 or the name of a GL_TEXTURE_2D"},
        {"draw view",
         [&] { return fk_engine_draw_view(e.get(), 4, &frame, good.data(), 4, fb->get()); },
         "fk_engine_draw_view: view: expected 0..3, got 4"},
    };
    for (const Case& c : cases) {
        EXPECT_LT(c.call(), 0) << c.what;
        EXPECT_NE(std::string(fk_error(e.get())).find(c.message), std::string::npos)
            << c.what << ": " << fk_error(e.get());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << c.what;
    }
    EXPECT_EQ(fk_engine_set_method(e.get(), "compute"), 0);
    EXPECT_STREQ(fk_error(e.get()), "");
    // Nothing drawn, and the refused occlusion calls left the last measurement alone.
    auto image = gl::readTextureRgba(color.get(), scene.width, scene.height);
    double sum = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) sum += image->at(x, y).r;
    EXPECT_EQ(sum, 0.0);
    EXPECT_EQ(readCoverage(e.get(), 4), measured);
    EXPECT_EQ(fk_engine_occlusion(nullptr, &frame, good.data(), 4), -1);
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

namespace {
//! An application's occluder pass for texture-mask: its opaque mesh in black, then each
//! translucent box multiplying the tile by 1 - opacity (front faces only).
class OccluderPass {
  public:
    explicit OccluderPass(const Scene& scene) {
        Scene opaque = scene, clear = scene;
        opaque.boxes.clear(), clear.boxes.clear(), clear.spheres.clear(), clear.triangles.clear();
        clear.ground.reset();
        for (const Box& b : scene.boxes) (b.opacity < 1 ? clear : opaque).boxes.push_back(b);
        m_opaque = uploadPositions(buildSceneMesh(opaque), m_opaqueVao, m_opaqueBuffer);
        m_clear = uploadPositions(buildSceneMesh(clear), m_clearVao, m_clearBuffer);
        for (const Box& b : clear.boxes) m_opacities.push_back(float(b.opacity));
        auto p = gl::linkProgram(
            {{GL_VERTEX_SHADER, "occluder.vert",
              "#version 450 core\nlayout(location = 0) in vec3 p;\nuniform mat4 vp;\n"
              "void main() { gl_Position = vp * vec4(p, 1.0); }\n"},
             {GL_FRAGMENT_SHADER, "occluder.frag",
              "#version 450 core\nuniform float keep;\nout vec4 c;\n"
              "void main() { c = vec4(keep, keep, keep, 1.0); }\n"}});
        m_program = std::move(*p);
    }
    static void draw(void* user, int, int, const float* vp, unsigned framebuffer, const int*) {
        auto* self = static_cast<OccluderPass*>(user);
        ++self->calls;
        EXPECT_EQ(glIsFramebuffer(framebuffer), GL_TRUE);
        const GLuint p = self->m_program.get();
        glUseProgram(p);
        glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "vp"), 1, GL_FALSE, vp);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glProgramUniform1f(p, glGetUniformLocation(p, "keep"), 0.f);
        glBindVertexArray(self->m_opaqueVao.get());
        glDrawArrays(GL_TRIANGLES, 0, self->m_opaque);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ZERO, GL_SRC_COLOR);
        glEnable(GL_CULL_FACE);
        glBindVertexArray(self->m_clearVao.get());
        for (std::size_t i = 0; i < self->m_opacities.size(); ++i) {
            glProgramUniform1f(p, glGetUniformLocation(p, "keep"), 1.f - self->m_opacities[i]);
            glDrawArrays(GL_TRIANGLES, GLint(36 * i), 36);
        }
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
    }
    int calls = 0;

  private:
    gl::VertexArray m_opaqueVao, m_clearVao;
    gl::Buffer m_opaqueBuffer, m_clearBuffer;
    GLsizei m_opaque = 0, m_clear = 0;
    std::vector<float> m_opacities;
    gl::Program m_program;
};
}  // namespace

TEST(Engine, TextureMaskDrawsSunMapsThroughTheOccluderCallbackEvenOffScreen) {
    // Lamps among boxes and spheres behind translucent cards, plus lamps past every edge of the
    // frame: the sun maps see them all, exactly as the ray caster does.
    Scene scene = lampScene(40, 21, true, 640, 360);
    for (const Vec3 off :
         {Vec3{6, 1.7, -4}, Vec3{-6, 2, -4}, Vec3{0.5, 5.5, -4}, Vec3{0, 1.7, 10}}) {
        SceneLight l = scene.lights.front();
        l.position = off;
        l.radius = 0.3;
        scene.lights.push_back(l);
    }
    scene.boxes.push_back({{2, 0, -2.05}, {3, 4, -2}});  // half in front of the first
    const VisibilityResult rays = truth(scene);
    EnginePtr e = makeEngine(int(scene.lights.size()));
    ASSERT_EQ(fk_engine_set_method(e.get(), "texture-mask"), 0) << fk_error(e.get());
    const std::vector<fk_light> lights = engineLights(scene, -1);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    EXPECT_LT(fk_engine_occlusion(e.get(), &frame, lights.data(), int(lights.size())), 0);
    EXPECT_NE(std::string(fk_error(e.get())).find("expected an occluder callback"),
              std::string::npos);
    OccluderPass occluders(scene);
    ASSERT_EQ(fk_engine_set_occluder_callback(e.get(), &OccluderPass::draw, &occluders), 0);
    const AppState before = readState();
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), int(lights.size())), 0)
        << fk_error(e.get());
    EXPECT_TRUE(readState() == before);  // whatever the callback did
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_EQ(occluders.calls, int(lights.size()));
    const std::vector<float> coverage = readCoverage(e.get(), int(lights.size()));
    int partial = 0;
    EXPECT_LE(worstError(coverage, rays, &partial), kTolerance);
    EXPECT_GE(partial, 5);
    const std::size_t first = lights.size() - 4;
    EXPECT_GT(coverage[first], 0.2f);  // off screen, half hidden, still measured
    EXPECT_LT(coverage[first], 0.8f);
    EXPECT_EQ(rays.lights[first].inFrame, 0.0);
}

TEST(Engine, TheCppWrapperGivesTheSameCoverageAsTheCApi) {
    const Scene scene = wallScene();
    glContext();
    flarekit::api::Engine cpp(4);
    ASSERT_TRUE(cpp.valid()) << cpp.createError();
    EXPECT_FALSE(flarekit::api::Engine(0).valid());
    std::string error;
    EXPECT_LT(cpp.loadPreset("no-such-preset", &error), 0);
    EXPECT_NE(error.find("fk_engine_load_preset"), std::string::npos) << error;
    const int preset = cpp.loadPreset("subtle");
    ASSERT_GE(preset, 0);
    const std::vector<fk_light> lights = engineLights(scene, preset);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_MINUS_ONE_TO_ONE);
    DepthPass(scene).draw(target, frame);
    ASSERT_TRUE(cpp.occlusion(frame, lights)) << cpp.occlusion(frame, lights).error;
    std::vector<float> viaCpp(4);
    ASSERT_EQ(cpp.readCoverage(viaCpp), 4);
    EnginePtr c = makeEngine(4);
    ASSERT_EQ(fk_engine_load_preset(c.get(), "subtle"), preset);
    ASSERT_EQ(fk_engine_occlusion(c.get(), &frame, lights.data(), 4), 0);
    EXPECT_EQ(viaCpp, readCoverage(c.get(), 4));
    const flarekit::api::Outcome bad = cpp.setMethod("pbo");
    EXPECT_FALSE(bad);
    EXPECT_NE(bad.error.find("fk_engine_set_method: method: expected"), std::string::npos);
    flarekit::api::Engine moved = std::move(cpp);
    EXPECT_TRUE(moved.valid());
    EXPECT_FALSE(cpp.valid());  // NOLINT(bugprone-use-after-move): moved-from is empty
    EXPECT_NE(moved.coverageTexture(), 0u);
}

TEST(Engine, CallsWithoutACurrentContextReturnAnErrorInsteadOfAborting) {
    EnginePtr e = makeEngine(4);
    const Scene scene = wallScene();
    const std::vector<fk_light> lights = engineLights(scene, -1);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_MINUS_ONE_TO_ONE);
    const EGLDisplay display = eglGetCurrentDisplay();
    const EGLContext context = eglGetCurrentContext();
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    const int occlusion = fk_engine_occlusion(e.get(), &frame, lights.data(), 4);
    const std::string message = fk_error(e.get());
    fk_engine* none = fk_engine_create(4);
    const std::string createMessage = fk_error(nullptr);
    const int samples = fk_engine_set_samples(e.get(), 16);  // no GL: still fine
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context));
    EXPECT_LT(occlusion, 0);
    EXPECT_NE(message.find("fk_engine_occlusion: no OpenGL context is current"), std::string::npos)
        << message;
    EXPECT_EQ(none, nullptr);
    EXPECT_NE(createMessage.find("no OpenGL context is current"), std::string::npos);
    EXPECT_EQ(samples, 0);
    EXPECT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 4), 0) << fk_error(e.get());
}
