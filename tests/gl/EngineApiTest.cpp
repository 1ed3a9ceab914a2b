// SPDX-License-Identifier: Apache-2.0
// The engine API's contract with the application: the GL state it must leave alone, every
// bad argument refused by name, the C++ wrapper giving what the C calls give, and calls
// without a current context returning an error.
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
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 5, appBuffer, 0, 64);
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, 0);
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
    EXPECT_EQ(fk_engine_occlusion(nullptr, &frame, good.data(), 4), FK_ERROR_INVALID);
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
