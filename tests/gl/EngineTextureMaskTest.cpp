// SPDX-License-Identifier: Apache-2.0
// texture-mask through the engine API: sun maps drawn by an application's occluder callback
// measure every light as the ray caster does, translucent cards and off-screen lights included.
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
