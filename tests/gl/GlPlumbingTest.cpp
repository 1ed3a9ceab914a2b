// SPDX-License-Identifier: Apache-2.0
// The GL plumbing on whatever EGL gives this machine (llvmpipe in CI). These tests never
// skip: a machine without a working headless GL fails them, loudly.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "GlTestContext.h"
#include "flarekit/PostFx.h"
#include "flarekit/gl/GpuFlare.h"
#include "flarekit/gl/GpuVisibility.h"
#include "flarekit/gl/HeadlessGl.h"
#include "flarekit/gl/Render.h"
#include "gl/GlObjects.h"

using namespace flarekit;
using namespace flarekit::gl;

namespace {
HeadlessGl& context() {
    return test::glContext();
}

const char* kFullscreenVs = R"(#version 450 core
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // one triangle covering the viewport
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";
}  // namespace

TEST(GlPlumbing, CreatesA45CoreContext) {
    HeadlessGl& gl = context();
    EXPECT_EQ(gl.version().rfind("4.", 0), 0u) << gl.version();
    EXPECT_NE(gl.version().find("Core"), std::string::npos) << gl.version();
    std::printf("GL: %s on %s via %s\n", gl.version().c_str(), gl.renderer().c_str(),
                gl.platform().c_str());
}

TEST(GlPlumbing, RendersIntoAFloatTargetAndReadsItBack) {
    context();
    const int w = 37, h = 11;
    Texture color = makeTexture2D(GL_RGBA32F, w, h);
    auto fb = makeFramebuffer(color);
    ASSERT_TRUE(fb.ok()) << fb.error().message;
    auto program = linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", kFullscreenVs},
                                {GL_FRAGMENT_SHADER, "coord.frag", R"(#version 450 core
out vec4 color;
void main() { color = vec4(gl_FragCoord.xy, 50.0, 0.25); })"}});
    ASSERT_TRUE(program.ok()) << program.error().message;
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    VertexArray vertexArray(vao);
    glBindFramebuffer(GL_FRAMEBUFFER, fb->get());
    glViewport(0, 0, w, h);
    glUseProgram(program->get());
    glBindVertexArray(vao);
    TimerQuery timer;
    timer.begin();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    timer.end();
    std::vector<float> pixels(std::size_t(w * h * 4));
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float* p = &pixels[std::size_t((y * w + x) * 4)];
            ASSERT_EQ(p[0], float(x) + 0.5f);  // pixel centres, HDR values kept exactly
            ASSERT_EQ(p[1], float(y) + 0.5f);
            ASSERT_EQ(p[2], 50.f);
            ASSERT_EQ(p[3], 0.25f);
        }
    }
    EXPECT_GE(timer.milliseconds(), 0.0);
}

TEST(GlPlumbing, CompileErrorsComeBackWithTheLog) {
    context();
    auto program = linkProgram({{GL_FRAGMENT_SHADER, "broken.frag",
                                 "#version 450 core\nvoid main() { undefined_thing; }"}});
    ASSERT_FALSE(program.ok());
    EXPECT_EQ(program.error().message.rfind("OpenGL: broken.frag: compile error: ", 0), 0u)
        << program.error().message;
    EXPECT_NE(program.error().message.find("undefined_thing"), std::string::npos)
        << program.error().message;
}

TEST(GlPlumbing, NamesAreMoveOnlyOwners) {
    context();
    Texture a = makeTexture2D(GL_RGBA8, 4, 4);
    const GLuint name = a.get();
    EXPECT_TRUE(glIsTexture(name));
    Texture b = std::move(a);
    EXPECT_EQ(a.get(), 0u);
    EXPECT_EQ(b.get(), name);
    b.reset();
    EXPECT_FALSE(glIsTexture(name));
}

TEST(GlPlumbing, AMisspeltUniformIsAnErrorButAnOptimisedOutOneIsNot) {
    context();  // the GL tests run with FLAREKIT_STRICT_GL=1 (tests/CMakeLists.txt)
    auto program = linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", kFullscreenVs},
                                {GL_FRAGMENT_SHADER, "u.frag", R"(#version 450 core
uniform float used;
uniform float unusedButDeclared;
uniform float weights[4];
out vec4 color;
void main() { color = vec4(used + weights[2]); })"}});
    ASSERT_TRUE(program.ok()) << program.error().message;
    EXPECT_TRUE(checkError("before").ok());
    EXPECT_GE(uniformLocation(program->get(), "used"), 0);
    EXPECT_GE(uniformLocation(program->get(), "weights[2]"), 0);
    EXPECT_EQ(uniformLocation(program->get(), "unusedButDeclared"), -1);  // compiled away: fine
    EXPECT_TRUE(checkError("declared names").ok());
    EXPECT_EQ(uniformLocation(program->get(), "uesd"), -1);
    EXPECT_EQ(uniformLocation(program->get(), "use"), -1);  // a prefix of a real name is not it
    const Status s = checkError("setting uniforms");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, "OpenGL: setting uniforms: the program has no uniform 'uesd'");
    EXPECT_TRUE(checkError("after").ok());  // reported once
}

// Every GL class asked to start without a current context says so: an error, not libepoxy's
// abort. A fresh thread has no context current, whatever the test process made elsewhere.
TEST(GlPlumbing, NoCurrentContextIsAnErrorNotAnAbort) {
    std::vector<std::string> errors;
    std::thread([&] {
        auto note = [&](const auto& result) {
            errors.push_back(result.ok() ? std::string("ok") : result.error().message);
        };
        note(GpuPostFx::create());
        note(SceneRenderer::create(Scene{}));
        note(GpuTonemap::create(64, 64));
        note(GpuTemporalFilter::create());
        Preset preset;
        preset.elements = {defaultElement(ElementType::Glow)};
        note(GpuSpriteFlare::create(preset, 64));
        note(createGpuVisibility("query", Scene{}));
    }).join();
    ASSERT_EQ(errors.size(), 6u);
    for (const std::string& e : errors)
        EXPECT_NE(e.find("no OpenGL context is current on this thread"), std::string::npos) << e;
}
