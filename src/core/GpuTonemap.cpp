// GpuTonemap: shaders/tonemap_aces.frag from the renderer's HDR colour into an RGBA16F
// display target (linear [0, 1], like tonemapAcesFitted's output).
#include <algorithm>

#include "flarekit/GpuFlare.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"

namespace flarekit {

struct GpuTonemap::Impl {
    int width = 0, height = 0;
    gl::Program program;
    gl::VertexArray vao;
    gl::Texture display;
    gl::Framebuffer target;
};

Result<GpuTonemap> GpuTonemap::create(int width, int height) {
    if (width < 1 || height < 1) return invalidInput("tonemap: empty frame");
    auto program = gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                                    {GL_FRAGMENT_SHADER, "tonemap_aces.frag", shaders::tonemap_aces_frag}});
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

Status GpuTonemap::apply(const SceneRenderer& source, unsigned exposureTexture, int channel) {
    if (source.width() != m->width || source.height() != m->height) {
        return invalidInput("tonemap: frame size differs from the display target's");
    }
    const GLuint p = m->program.get();
    glProgramUniform1i(p, glGetUniformLocation(p, "exposureChannel"), exposureTexture ? channel : -1);
    glBindFramebuffer(GL_FRAMEBUFFER, m->target.get());
    glViewport(0, 0, m->width, m->height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, source.colorTexture());
    glBindTextureUnit(1, exposureTexture);
    glBindVertexArray(m->vao.get());
    glUseProgram(p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
        return internalError("OpenGL: tone-map pass failed (error 0x" + std::to_string(err) + ")");
    }
    return Ok{};
}

Result<Image> GpuTonemap::read() const {
    Image image(m->width, m->height);
    const std::size_t rowFloats = std::size_t(m->width) * 4;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // In bands: a GLsizei byte count overflows past 2 GiB (a 16k frame is 4 GiB of floats).
    const std::size_t rowBytes = rowFloats * sizeof(float);
    const int bandRows = int(std::max<std::size_t>(1, (std::size_t(1) << 30) / rowBytes));
    for (int y = 0; y < m->height; y += bandRows) {
        const int rows = std::min(bandRows, m->height - y);
        glGetTextureSubImage(m->display.get(), 0, 0, y, 0, m->width, rows, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(rowBytes * std::size_t(rows)), image.row(y));
    }
    // GL rows are bottom-up: flip in place.
    for (int y = 0; y < m->height / 2; ++y) {
        std::swap_ranges(image.row(y), image.row(y) + rowFloats, image.row(m->height - 1 - y));
    }
    if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
        return internalError("OpenGL: reading the tone-mapped frame failed (error 0x" + std::to_string(err) + ")");
    }
    return image;
}

}  // namespace flarekit
