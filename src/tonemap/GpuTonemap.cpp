// SPDX-License-Identifier: Apache-2.0
// GpuTonemap: shaders/tonemap_aces.frag from the renderer's HDR colour into an RGBA16F
// display target (linear [0, 1], like tonemapAcesFitted's output).
#include "flarekit/gl/GpuFlare.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "scene/SceneTargets.h"

namespace flarekit {

struct GpuTonemap::Impl {
    int width = 0, height = 0;
    gl::Program program;
    gl::VertexArray vao;
    gl::Texture display;
    gl::Framebuffer target;
};

Result<GpuTonemap> GpuTonemap::create(int width, int height) {
    if (Status s = gl::requireCurrentContext("GpuTonemap::create"); !s) return s.error();
    if (width < 1 || height < 1) return invalidInput("tonemap: empty frame");
    auto program = gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                                    {GL_FRAGMENT_SHADER, "tonemap_aces.frag",
                                     std::string("#version 450 core\n") +
                                         shaders::tone_curves_glsl + shaders::tonemap_aces_frag}});
    if (!program) return program.error();
    auto m = std::make_unique<Impl>();
    m->width = width, m->height = height;
    m->program = std::move(*program);
    m->vao = gl::makeVertexArray();
    m->display = gl::makeTexture2D(GL_RGBA16F, width, height);
    auto fb = gl::makeFramebuffer(m->display);
    if (!fb) return fb.error();
    m->target = std::move(*fb);
    return GpuTonemap(std::move(m));
}

GpuTonemap::GpuTonemap(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
GpuTonemap::~GpuTonemap() = default;
GpuTonemap::GpuTonemap(GpuTonemap&&) noexcept = default;
GpuTonemap& GpuTonemap::operator=(GpuTonemap&&) noexcept = default;

Status GpuTonemap::apply(const SceneRenderer& source, GpuChannel exposure) {
    if (source.width() != m->width || source.height() != m->height) {
        return invalidInput("tonemap: frame size differs from the display target's");
    }
    const GLuint p = m->program.get();
    glProgramUniform1i(p, gl::uniformLocation(p, "exposureChannel"),
                       exposure ? exposure.channel : -1);
    glBindFramebuffer(GL_FRAMEBUFFER, m->target.get());
    glViewport(0, 0, m->width, m->height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, sceneTargets(source).color);
    glBindTextureUnit(1, exposure.texture);
    glBindVertexArray(m->vao.get());
    glUseProgram(p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return gl::checkError("tone-map pass");
}

Result<Image> GpuTonemap::read() const {
    return gl::readTextureRgba(m->display.get(), m->width, m->height);
}

}  // namespace flarekit
