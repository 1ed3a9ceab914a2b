// SPDX-License-Identifier: Apache-2.0
// An application's own depth pass, as a game would have it, for testing the engine API apart
// from flarekit's SceneRenderer: the scene's opaque mesh drawn into a depth texture (2D or
// multisampled, DEPTH_COMPONENT32F or DEPTH24_STENCIL8) inside any viewport of it, under any of
// the three depth conventions, with its own matrices and its own shader.
#pragma once

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "flarekit/flarekit.h"
#include "flarekit/gl/EngineScene.h"
#include "gl/GlObjects.h"
#include "scene/CameraMath.h"
#include "scene/SceneMesh.h"

namespace flarekit::test {

struct DepthTarget {
    gl::Texture depth;
    gl::Framebuffer framebuffer;
    int width = 0, height = 0, samples = 1;
};

inline DepthTarget makeDepthTarget(int width, int height, int samples, GLenum format) {
    DepthTarget t;
    t.width = width, t.height = height, t.samples = samples;
    GLuint name = 0;
    if (samples > 1) {
        glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &name);
        glTextureStorage2DMultisample(name, samples, format, width, height, GL_TRUE);
    } else {
        glCreateTextures(GL_TEXTURE_2D, 1, &name);
        glTextureStorage2D(name, 1, format, width, height);
    }
    t.depth = gl::Texture(name);
    GLuint fb = 0;
    glCreateFramebuffers(1, &fb);
    glNamedFramebufferTexture(
        fb, format == GL_DEPTH24_STENCIL8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, name,
        0);
    glNamedFramebufferDrawBuffer(fb, GL_NONE);
    t.framebuffer = gl::Framebuffer(fb);
    return t;
}

//! The projection for `convention`: classic gluPerspective, the same mapped to [0, 1], or
//! reversed-Z with an infinite far plane.
inline std::array<float, 16> projectionFor(const SceneCamera& c, double aspect,
                                           fk_depth_convention convention) {
    const double f = 1.0 / std::tan(c.fovYDeg * std::numbers::pi / 360.0);
    const double n = c.nearPlane, far = c.farPlane;
    std::array<float, 16> p{};
    p[0] = float(f / aspect);
    p[5] = float(f);
    p[11] = -1.f;
    if (convention == FK_DEPTH_MINUS_ONE_TO_ONE) {
        p[10] = float((far + n) / (n - far));
        p[14] = float(2 * far * n / (n - far));
    } else if (convention == FK_DEPTH_ZERO_TO_ONE) {
        p[10] = float(far / (n - far));
        p[14] = float(far * n / (n - far));
    } else {
        p[10] = 0.f;
        p[14] = float(n);
    }
    return p;
}

inline fk_frame frameFor(const Scene& scene, const DepthTarget& t, std::array<int, 4> viewport,
                         fk_depth_convention convention, float dt = 1.f / 60.f) {
    fk_frame f{};
    f.depth_texture = t.depth.get();
    f.width = t.width;
    f.height = t.height;
    for (int i = 0; i < 4; ++i) f.viewport[i] = viewport[std::size_t(i)];
    f.depth_convention = convention;
    const auto view = toFloat(lookAtMatrix(scene.camera));
    const auto proj =
        projectionFor(scene.camera, double(viewport[2]) / double(viewport[3]), convention);
    for (int i = 0; i < 16; ++i)
        f.view[i] = view[std::size_t(i)], f.projection[i] = proj[std::size_t(i)];
    f.dt_seconds = dt;
    return f;
}

//! `mesh` into a new buffer with its positions at attribute 0 of a new vertex array (an empty
//! mesh gets a one-vertex buffer, since GL refuses an empty one); its vertex count.
inline GLsizei uploadPositions(const std::vector<MeshVertex>& mesh, gl::VertexArray& vao,
                               gl::Buffer& buffer) {
    GLuint b = 0, a = 0;
    glCreateBuffers(1, &b);
    const MeshVertex none{};
    glNamedBufferStorage(b, GLsizeiptr(std::max<std::size_t>(1, mesh.size()) * sizeof(MeshVertex)),
                         mesh.empty() ? &none : mesh.data(), 0);
    buffer = gl::Buffer(b);
    glCreateVertexArrays(1, &a);
    glVertexArrayVertexBuffer(a, 0, b, 0, sizeof(MeshVertex));
    glEnableVertexArrayAttrib(a, 0);
    glVertexArrayAttribFormat(a, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(a, 0, 0);
    vao = gl::VertexArray(a);
    return GLsizei(mesh.size());
}

//! Draws the scene's opaque objects into `t` inside `frame.viewport`, the way `frame` says.
class DepthPass {
  public:
    explicit DepthPass(const Scene& scene) {
        m_count = uploadPositions(buildSceneMesh(opaqueObjects(scene)), m_vao, m_buffer);
        auto p = gl::linkProgram(
            {{GL_VERTEX_SHADER, "app_depth.vert",
              "#version 450 core\nlayout(location = 0) in vec3 p;\nuniform mat4 vp;\n"
              "void main() { gl_Position = vp * vec4(p, 1.0); }\n"},
             {GL_FRAGMENT_SHADER, "app_depth.frag", "#version 450 core\nvoid main() {}\n"}});
        m_program = std::move(*p);
    }

    void draw(const DepthTarget& t, const fk_frame& frame) const {
        std::array<float, 16> vp{};
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                float sum = 0;
                for (int k = 0; k < 4; ++k)
                    sum += frame.projection[k * 4 + r] * frame.view[c * 4 + k];
                vp[std::size_t(c * 4 + r)] = sum;
            }
        const bool reversed = frame.depth_convention == FK_DEPTH_REVERSED_Z;
        glClipControl(GL_LOWER_LEFT, frame.depth_convention == FK_DEPTH_MINUS_ONE_TO_ONE
                                         ? GL_NEGATIVE_ONE_TO_ONE
                                         : GL_ZERO_TO_ONE);
        glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.get());
        glViewport(0, 0, t.width, t.height);
        glDepthMask(GL_TRUE);
        glClearDepth(reversed ? 0.0 : 1.0);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glViewport(frame.viewport[0], frame.viewport[1], frame.viewport[2], frame.viewport[3]);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(reversed ? GL_GREATER : GL_LESS);
        glDisable(GL_CULL_FACE);
        glProgramUniformMatrix4fv(m_program.get(), glGetUniformLocation(m_program.get(), "vp"), 1,
                                  GL_FALSE, vp.data());
        glUseProgram(m_program.get());
        glBindVertexArray(m_vao.get());
        glDrawArrays(GL_TRIANGLES, 0, m_count);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glDepthFunc(GL_LESS);
        glClearDepth(1.0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glUseProgram(0);
        glBindVertexArray(0);
    }

  private:
    gl::Buffer m_buffer;
    gl::VertexArray m_vao;
    gl::Program m_program;
    GLsizei m_count = 0;
};

//! The scene's lights with every flare drawn by `preset` (-1: none).
inline std::vector<fk_light> engineLights(const Scene& scene, int preset) {
    return flarekit::engineLights(scene, [preset](const std::string&) { return preset; });
}

}  // namespace flarekit::test
