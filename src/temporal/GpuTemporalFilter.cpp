// SPDX-License-Identifier: Apache-2.0
// GpuTemporalFilter: shaders/temporal_filter.frag over two 1x1 RGBA32F textures used in turn
// (read the previous, write the next), so no state ever leaves the GPU.
#include <array>

#include "flarekit/gl/GpuFlare.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"

namespace flarekit {

struct GpuTemporalFilter::Impl {
    TemporalParams params;
    gl::Program program;
    gl::VertexArray vao;
    std::array<gl::Texture, 2> states;
    std::array<gl::Framebuffer, 2> targets;
    gl::Texture consumed;  // R32F: the raw coverage the last update used (attachment 1 of both)
    int newest = 0;        // index of the texture holding the newest state
    bool started = false;
};

Result<GpuTemporalFilter> GpuTemporalFilter::create(const TemporalParams& params) {
    if (Status s = gl::requireCurrentContext("GpuTemporalFilter::create"); !s) return s.error();
    if (Status s = validateTemporalParams(params); !s) return s.error();
    auto program = gl::linkProgram(
        {{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
         {GL_FRAGMENT_SHADER, "temporal_filter.frag", shaders::temporal_filter_frag}});
    if (!program) return program.error();
    auto m = std::make_unique<Impl>();
    m->params = params;
    m->program = std::move(*program);
    m->vao = gl::makeVertexArray();
    const float initial[4] = {0.f, 0.f, 1.f, 0.f};  // TemporalState's defaults
    m->consumed = gl::makeTexture2D(GL_R32F, 1, 1);
    for (int i = 0; i < 2; ++i) {
        m->states[i] = gl::makeTexture2D(GL_RGBA32F, 1, 1);
        glTextureSubImage2D(m->states[i].get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, initial);
        auto fb = gl::makeFramebuffer(m->states[i]);
        if (!fb) return fb.error();
        m->targets[i] = std::move(*fb);
        glNamedFramebufferTexture(m->targets[i].get(), GL_COLOR_ATTACHMENT1, m->consumed.get(), 0);
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(m->targets[i].get(), 2, buffers);
    }
    return GpuTemporalFilter(std::move(m));
}

GpuTemporalFilter::GpuTemporalFilter(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
GpuTemporalFilter::~GpuTemporalFilter() = default;
GpuTemporalFilter::GpuTemporalFilter(GpuTemporalFilter&&) noexcept = default;
GpuTemporalFilter& GpuTemporalFilter::operator=(GpuTemporalFilter&&) noexcept = default;

GpuChannel GpuTemporalFilter::state(GpuStateChannel channel) const {
    return {m->states[std::size_t(m->newest)].get(), int(channel)};
}

Status GpuTemporalFilter::update(GpuChannel rawCoverage, Point sunPixel, bool sunInFront, int width,
                                 int height, double dtSeconds) {
    if (rawCoverage.channel < 0 || rawCoverage.channel > 3)
        return invalidInput("temporal filter: channel must be 0..3");
    const GLuint p = m->program.get();
    glProgramUniform1i(p, gl::uniformLocation(p, "rawChannel"), rawCoverage.channel);
    const TemporalParams& t = m->params;
    auto set = [p](const char* name, double v) {
        glProgramUniform1f(p, gl::uniformLocation(p, name), float(v));
    };
    glProgramUniform1i(p, gl::uniformLocation(p, "started"), m->started ? 1 : 0);
    set("dtSeconds", dtSeconds);
    set("attackSeconds", t.attackSeconds);
    set("releaseSeconds", t.releaseSeconds);
    set("adaptStrength", t.adaptStrength);
    set("adaptDarkenSeconds", t.adaptDarkenSeconds);
    set("adaptBrightenSeconds", t.adaptBrightenSeconds);
    set("edgeFadeNow", sunInFront ? edgeFade(sunPixel, width, height, t.guardBand) : 0.0);
    glProgramUniform2f(p, gl::uniformLocation(p, "sunPixel"), sunPixel.x, sunPixel.y);
    glProgramUniform2f(p, gl::uniformLocation(p, "frameSize"), float(width), float(height));

    const int next = 1 - m->newest;
    glBindFramebuffer(GL_FRAMEBUFFER, m->targets[std::size_t(next)].get());
    glViewport(0, 0, 1, 1);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glBindTextureUnit(0, m->states[std::size_t(m->newest)].get());
    glBindTextureUnit(1, rawCoverage.texture);
    glBindVertexArray(m->vao.get());
    glUseProgram(p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m->newest = next;
    m->started = true;
    return gl::checkError("temporal filter pass");
}

Result<TemporalState> GpuTemporalFilter::readState() const {
    float v[4] = {};
    glGetTextureImage(state(GpuStateChannel::Coverage).texture, 0, GL_RGBA, GL_FLOAT, sizeof v, v);
    TemporalState s;
    s.coverage = v[int(GpuStateChannel::Coverage)];
    s.edgeFade = v[int(GpuStateChannel::EdgeFade)];
    s.exposure = v[int(GpuStateChannel::Exposure)];
    s.flareWeight = v[int(GpuStateChannel::FlareWeight)];
    return s;
}

Result<double> GpuTemporalFilter::readConsumedCoverage() const {
    float v = 0;
    glGetTextureImage(m->consumed.get(), 0, GL_RED, GL_FLOAT, sizeof v, &v);
    return double(v);
}

}  // namespace flarekit
