// `burnout`: the Burnout Dominator chain (PSP), on GL. Over a 14x14 grid laid on the sun's
// square a white rectangle is drawn without depth test, then a black one at the far plane with
// the depth test, which leaves a binary mask of where the sun is visible; bilinear downsamples
// 14 -> 8 -> 4 -> 2 -> 1 average it to one value on the GPU, in 8-bit targets like the PSP's.
// Cells carry their share of the disc, so the result is the disc's coverage, not the square's.
#include <array>

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"

namespace flarekit::occlusion {

namespace {
//! The blog's grid and its downsample chain (burnout-dominator-psp-lens-flare.md).
constexpr int kGrid = 14;
constexpr std::array<int, 4> kChain = {8, 4, 2, 1};

class BurnoutMethod final : public GpuMethod {
public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto m = std::unique_ptr<BurnoutMethod>(new BurnoutMethod());
        auto white = linkWithDisc({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                                   {GL_FRAGMENT_SHADER, "burnout_white.frag", shaders::burnout_white_frag}});
        if (!white) return white.error();
        auto black = linkFullscreen("burnout_black.frag", shaders::burnout_black_frag);
        if (!black) return black.error();
        auto combine = linkFullscreen("burnout_combine.frag", shaders::burnout_combine_frag);
        if (!combine) return combine.error();
        auto down = linkFullscreen("burnout_downsample.frag", shaders::burnout_downsample_frag);
        if (!down) return down.error();
        auto resolve = linkFullscreen("resolve_ratio.frag", shaders::resolve_ratio_frag);
        if (!resolve) return resolve.error();
        m->m_white = std::move(*white), m->m_black = std::move(*black), m->m_combine = std::move(*combine);
        m->m_down = std::move(*down), m->m_resolve = std::move(*resolve);
        if (Status s = m->makeTargets(); !s) return s.error();
        return std::unique_ptr<GpuVisibility>(std::move(m));
    }
    std::string name() const override { return "burnout"; }
    int latencyFrames() const override { return 0; }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        const SunDiscView v = sunDiscView(view);
        if (v.empty() || !v.bounded) {
            publish(0.0);
            return Ok{};
        }
        // The square around the disc's projection, one cell = side / 14 pixels.
        const double side = std::max(v.rimX1 - v.rimX0, v.rimY1 - v.rimY0);
        const double cx = 0.5 * (v.rimX0 + v.rimX1), cy = 0.5 * (v.rimY0 + v.rimY1);
        const GLuint w = m_white.get();
        setSunDiscUniforms(w, v);
        glProgramUniform2f(w, glGetUniformLocation(w, "regionOrigin"), float(cx - side / 2), float(cy - side / 2));
        glProgramUniform1f(w, glGetUniformLocation(w, "cellSize"), float(side / kGrid));

        glBindVertexArray(m_vao.get());
        glDisable(GL_BLEND);
        glBindFramebuffer(GL_FRAMEBUFFER, m_maskTarget.get());
        glViewport(0, 0, kGrid, kGrid);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);  // white rectangle: no depth test (it also lays the depth copy)
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glBindTextureUnit(0, renderer.depthTexture());
        glUseProgram(w);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);  // black rectangle at the far plane: depth-tested
        glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
        glUseProgram(m_black.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);

        glBindFramebuffer(GL_FRAMEBUFFER, m_levels[0].target.get());
        glBindTextureUnit(0, m_mask.get());
        glUseProgram(m_combine.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const GLuint d = m_down.get();
        for (std::size_t i = 1; i < m_levels.size(); ++i) {
            const int n = m_levels[i].size;
            glBindFramebuffer(GL_FRAMEBUFFER, m_levels[i].target.get());
            glViewport(0, 0, n, n);
            glProgramUniform2f(d, glGetUniformLocation(d, "destinationSize"), float(n), float(n));
            glBindTextureUnit(0, m_levels[i - 1].texture.get());
            glUseProgram(d);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        if (m_coverageAttached != coverageName()) {
            glNamedFramebufferTexture(m_coverageTarget.get(), GL_COLOR_ATTACHMENT0, coverageName(), 0);
            m_coverageAttached = coverageName();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, m_coverageTarget.get());
        glViewport(0, 0, 1, 1);
        glBindTextureUnit(0, m_levels.back().texture.get());
        glUseProgram(m_resolve.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        markPublished();
        return gl::checkError("burnout: chain");
    }

private:
    struct Level {
        int size;
        gl::Texture texture;
        gl::Framebuffer target;
    };
    BurnoutMethod() {
        GLuint n = 0;
        glCreateVertexArrays(1, &n);
        m_vao = gl::VertexArray(n);
        glCreateFramebuffers(1, &n);
        m_coverageTarget = gl::Framebuffer(n);
    }
    Status makeTargets() {
        m_mask = gl::makeTexture2D(GL_RGBA8, kGrid, kGrid);
        m_maskDepth = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, kGrid, kGrid);
        auto target = gl::makeFramebuffer(m_mask, &m_maskDepth);
        if (!target) return target.error();
        m_maskTarget = std::move(*target);
        std::vector<int> sizes = {kGrid};
        sizes.insert(sizes.end(), kChain.begin(), kChain.end());
        for (int n : sizes) {  // level 0 holds the combined 14x14 values
            Level level{n, gl::makeTexture2D(GL_RGBA8, n, n), {}};
            auto fb = gl::makeFramebuffer(level.texture);
            if (!fb) return fb.error();
            level.target = std::move(*fb);
            m_levels.push_back(std::move(level));
        }
        return Ok{};
    }

    gl::Program m_white, m_black, m_combine, m_down, m_resolve;
    gl::VertexArray m_vao;
    gl::Texture m_mask, m_maskDepth;
    gl::Framebuffer m_maskTarget, m_coverageTarget;
    GLuint m_coverageAttached = 0;
    std::vector<Level> m_levels;
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeBurnoutMethod() { return BurnoutMethod::create(); }

}  // namespace flarekit::occlusion
