// SPDX-License-Identifier: Apache-2.0
// `compute`: the most accurate GPU estimate. A compute shader weighs every pixel of the disc's
// box by its area inside the disc and its solid angle (sun_disc.glsl's discWeight), sums the
// sky pixels' weights and all weights per 16x16 work group in shared memory, and a second
// one-group dispatch reduces the partials and writes the ratio into the 1x1 coverage texture.
// With an MSAA scene pass it reads every depth sample instead, for sub-pixel occluders.
#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"
#include "scene/SceneTargets.h"

namespace flarekit::occlusion {

namespace {
class ComputeMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto reduce =
            linkWithDisc({{GL_COMPUTE_SHADER, "disc_reduce.comp", shaders::disc_reduce_comp}});
        if (!reduce) return reduce.error();
        auto reduceMs =
            linkWithDisc({{GL_COMPUTE_SHADER, "disc_reduce.comp", shaders::disc_reduce_comp}},
                         "#define MULTISAMPLE\n");
        if (!reduceMs) return reduceMs.error();
        auto finish =
            linkWithDisc({{GL_COMPUTE_SHADER, "disc_finish.comp", shaders::disc_finish_comp}});
        if (!finish) return finish.error();
        auto m = std::unique_ptr<ComputeMethod>(
            new ComputeMethod(std::move(*reduce), std::move(*finish)));
        m->m_reduceMs = std::move(*reduceMs);
        return std::unique_ptr<GpuVisibility>(std::move(m));
    }
    std::string name() const override { return "compute"; }
    int latencyFrames() const override { return 0; }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        const SunDiscView v = sunDiscView(view);
        if (v.empty()) {
            publish(0.0);
            return Ok{};
        }
        const int w = v.x1 - v.x0, h = v.y1 - v.y0;
        const GLuint groupsX = GLuint((w + 15) / 16), groupsY = GLuint((h + 15) / 16);
        const GLsizeiptr bytes = GLsizeiptr(groupsX * groupsY * 2 * sizeof(float));
        if (bytes > m_capacity) {
            glNamedBufferData(m_partials.get(), bytes, nullptr, GL_DYNAMIC_COPY);
            m_capacity = bytes;
        }
        const bool multisample = renderer.msaaSamples() > 1;
        const GLuint r = multisample ? m_reduceMs.get() : m_reduce.get(), f = m_finish.get();
        setSunDiscUniforms(r, v);
        if (multisample)
            glProgramUniform1i(r, gl::uniformLocation(r, "sampleCount"), renderer.msaaSamples());
        glProgramUniform2i(r, gl::uniformLocation(r, "boxOrigin"), v.x0, v.y0);
        glProgramUniform2i(r, gl::uniformLocation(r, "boxSize"), w, h);
        glProgramUniform1i(f, gl::uniformLocation(f, "partialCount"), GLint(groupsX * groupsY));
        glBindTextureUnit(0, multisample ? sceneTargets(renderer).multisampleDepth
                                         : sceneTargets(renderer).depth);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m_partials.get());
        glUseProgram(r);
        glDispatchCompute(groupsX, groupsY, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        glBindImageTexture(0, coverageName(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        glUseProgram(f);
        glDispatchCompute(1, 1, 1);
        // Whoever reads the coverage next (a flare shader, or glGetTextureImage) sees the store.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        markPublished();
        return gl::checkError("compute: disc reduction");
    }

  private:
    ComputeMethod(gl::Program reduce, gl::Program finish)
        : m_reduce(std::move(reduce)), m_finish(std::move(finish)) {
        GLuint b = 0;
        glCreateBuffers(1, &b);
        m_partials = gl::Buffer(b);
    }
    gl::Program m_reduce, m_reduceMs, m_finish;
    gl::Buffer m_partials;
    GLsizeiptr m_capacity = 0;
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeComputeMethod() {
    return ComputeMethod::create();
}

}  // namespace flarekit::occlusion
