// SPDX-License-Identifier: Apache-2.0
// `burnout`: the Burnout Dominator chain (PSP), on GL. Over the sun's square a white rectangle
// is drawn without depth test, then a black one at the far plane with the depth test, which
// leaves a binary mask of where the sun is visible; it is summed into the blog's 14x14 grid
// and bilinear downsamples 14 -> 8 -> 4 -> 2 -> 1 average that to one value on the GPU.
// Where the PSP's mask is 14x14 pixels around a sun of about that size, here the sun's disc has
// any size, so each of the 14x14 cells is a block of 4x4 mask texels (sub-cells) and counts
// the share of its area that is visible. Cells carry their share of the disc and the inverse
// of the chain's uneven bilinear weights, so the result is the disc's coverage, not the
// square's, and an occluder weighs the same wherever it crosses the grid.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flarekit_shaders.h"
#include "occlusion/FrameDepth.h"
#include "occlusion/GpuMethod.h"

namespace flarekit::occlusion {

namespace {
//! The blog's grid and its downsample chain (burnout-dominator-psp-lens-flare.md).
constexpr int kGrid = 14;
constexpr std::array<int, 4> kChain = {8, 4, 2, 1};
//! Mask texels per cell side: 4 puts a 32 px disc's sub-cells at 0.6 px, finer than the frame.
constexpr int kSubCells = 4;

//! How much each of the 14 grid columns (or rows) weighs in the chain's one output: the
//! chain run on unit impulses, with GL's bilinear tap at each destination texel's centre.
std::array<double, kGrid> chainWeights() {
    std::array<double, kGrid> weights{};
    for (int k = 0; k < kGrid; ++k) {
        std::vector<double> level(kGrid, 0.0);
        level[std::size_t(k)] = 1.0;
        for (int n : kChain) {
            std::vector<double> next(std::size_t(n), 0.0);
            const int size = int(level.size());
            for (int i = 0; i < n; ++i) {
                const double x = (i + 0.5) * size / n - 0.5;  // source texel coordinate of the tap
                const int x0 = int(std::floor(x));
                const double f = x - x0;
                auto at = [&](int t) { return level[std::size_t(std::clamp(t, 0, size - 1))]; };
                next[std::size_t(i)] = (1 - f) * at(x0) + f * at(x0 + 1);
            }
            level = std::move(next);
        }
        weights[std::size_t(k)] = level[0];
    }
    return weights;
}

class BurnoutMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto m = std::unique_ptr<BurnoutMethod>(new BurnoutMethod());
        auto white = FrameDepthProgram::link(
            {{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
             {GL_FRAGMENT_SHADER, "burnout_white.frag", shaders::burnout_white_frag}});
        if (!white) return white.error();
        m->m_white = std::move(*white);
        auto black = linkFullscreen("burnout_black.frag", shaders::burnout_black_frag);
        if (!black) return black.error();
        auto combine = linkWithDisc(
            {{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
             {GL_FRAGMENT_SHADER, "burnout_combine.frag", shaders::burnout_combine_frag}});
        if (!combine) return combine.error();
        auto down = linkFullscreen("burnout_downsample.frag", shaders::burnout_downsample_frag);
        if (!down) return down.error();
        auto resolve = linkFullscreen("resolve_ratio.frag", shaders::resolve_ratio_frag);
        if (!resolve) return resolve.error();
        m->m_black = std::move(*black), m->m_combine = std::move(*combine);
        const std::array<double, kGrid> weights = chainWeights();
        const double lightest = *std::min_element(weights.begin(), weights.end());
        std::array<float, kGrid> compensation{};
        for (int k = 0; k < kGrid; ++k)
            compensation[std::size_t(k)] = float(lightest / weights[std::size_t(k)]);
        const GLuint c = m->m_combine.get();
        glProgramUniform1fv(c, gl::uniformLocation(c, "compensation"), kGrid, compensation.data());
        glProgramUniform1i(c, gl::uniformLocation(c, "subCells"), kSubCells);
        m->m_down = std::move(*down), m->m_resolve = std::move(*resolve);
        if (Status s = m->makeTargets(); !s) return s.error();
        return std::unique_ptr<GpuVisibility>(std::move(m));
    }
    std::string name() const override { return "burnout"; }
    int latencyFrames() const override { return 0; }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        const SunDiscView v = sunDiscView(view);
        m_drewChain = false;
        if (v.empty() || !v.bounded) {
            publish(0.0);
            return Ok{};
        }
        // The square around the disc's projection, one cell = side / 14 pixels.
        const double side = std::max(v.rimX1 - v.rimX0, v.rimY1 - v.rimY0);
        const double cx = 0.5 * (v.rimX0 + v.rimX1), cy = 0.5 * (v.rimY0 + v.rimY1);
        const float originX = float(cx - side / 2), originY = float(cy - side / 2);
        const GLuint w = m_white.forFrame(renderer);
        setSunDiscUniforms(w, v);
        glProgramUniform2f(w, gl::uniformLocation(w, "regionOrigin"), originX, originY);
        glProgramUniform1f(w, gl::uniformLocation(w, "subCellSize"),
                           float(side / (kGrid * kSubCells)));
        const GLuint c = m_combine.get();
        setSunDiscUniforms(c, v);
        glProgramUniform2f(c, gl::uniformLocation(c, "regionOrigin"), originX, originY);
        glProgramUniform1f(c, gl::uniformLocation(c, "cellSize"), float(side / kGrid));

        glBindVertexArray(m_vao.get());
        glDisable(GL_BLEND);
        glBindFramebuffer(GL_FRAMEBUFFER, m_maskTarget.get());
        glViewport(0, 0, kGrid * kSubCells, kGrid * kSubCells);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);  // white rectangle: no depth test (it also lays the depth copy)
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        m_white.bindDepth(renderer);
        glUseProgram(w);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);  // black rectangle at the far plane: depth-tested
        glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
        glProgramUniform1f(m_black.get(), gl::uniformLocation(m_black.get(), "lightDepth"),
                           float(v.lightDepth));
        glUseProgram(m_black.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);

        glBindFramebuffer(GL_FRAMEBUFFER, m_levels[0].target.get());
        glViewport(0, 0, kGrid, kGrid);
        glBindTextureUnit(0, m_mask.get());
        glUseProgram(c);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const GLuint d = m_down.get();
        for (std::size_t i = 1; i < m_levels.size(); ++i) {
            const int n = m_levels[i].size;
            glBindFramebuffer(GL_FRAMEBUFFER, m_levels[i].target.get());
            glViewport(0, 0, n, n);
            glProgramUniform2f(d, gl::uniformLocation(d, "destinationSize"), float(n), float(n));
            glBindTextureUnit(0, m_levels[i - 1].texture.get());
            glUseProgram(d);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        if (m_coverageAttached != coverageName()) {
            glNamedFramebufferTexture(m_coverageTarget.get(), GL_COLOR_ATTACHMENT0, coverageName(),
                                      0);
            m_coverageAttached = coverageName();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, m_coverageTarget.get());
        glViewport(0, 0, 1, 1);
        glBindTextureUnit(0, m_levels.back().texture.get());
        glUseProgram(m_resolve.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        markPublished();
        m_drewChain = true;
        return gl::checkError("burnout: chain");
    }
    //! The mask at sub-cell resolution, the 14x14 grid and each level of the chain.
    std::vector<MethodView> views() const override {
        if (!m_drewChain) return {};
        const int maskSide = kGrid * kSubCells;
        const std::string mask = std::to_string(maskSide);
        std::vector<MethodView> out = {
            readMethodView(m_mask.get(), maskSide, maskSide, "mask " + mask + "x" + mask)};
        for (const Level& level : m_levels) {
            const std::string n = std::to_string(level.size);
            out.push_back(readMethodView(level.texture.get(), level.size, level.size,
                                         (level.size == kGrid ? "grid " : "chain ") + n + "x" + n));
        }
        return out;
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
        m_mask = gl::makeTexture2D(GL_RGBA8, kGrid * kSubCells, kGrid * kSubCells);
        m_maskDepth =
            gl::makeTexture2D(GL_DEPTH_COMPONENT32F, kGrid * kSubCells, kGrid * kSubCells);
        auto target = gl::makeFramebuffer(m_mask, &m_maskDepth);
        if (!target) return target.error();
        m_maskTarget = std::move(*target);
        std::vector<int> sizes = {kGrid};
        sizes.insert(sizes.end(), kChain.begin(), kChain.end());
        for (int n : sizes) {  // level 0 holds the combined 14x14 values
            Level level{n, gl::makeTexture2D(GL_RGBA16, n, n), {}};
            auto fb = gl::makeFramebuffer(level.texture);
            if (!fb) return fb.error();
            level.target = std::move(*fb);
            m_levels.push_back(std::move(level));
        }
        return Ok{};
    }

    FrameDepthProgram m_white;
    gl::Program m_black, m_combine, m_down, m_resolve;
    gl::VertexArray m_vao;
    gl::Texture m_mask, m_maskDepth;
    gl::Framebuffer m_maskTarget, m_coverageTarget;
    GLuint m_coverageAttached = 0;
    std::vector<Level> m_levels;
    bool m_drewChain = false;  //!< the last measure() drew the chain (the sun was in frame)
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeBurnoutMethod() {
    return BurnoutMethod::create();
}

}  // namespace flarekit::occlusion
