// SPDX-License-Identifier: Apache-2.0
// `texture-mask-screen`: texture masking without the re-render. The sun map's texels look up
// the main frame's depth along their rays (sky = sun visible), 4 x 4 rays a texel so the map
// holds area shares, not one point each, then the same point sum (float: the map is
// fractional). Only what is on screen can be measured; off-screen texels leave the
// normalisation.
#include <cmath>
#include <numbers>

#include "flarekit_shaders.h"
#include "occlusion/FrameDepth.h"
#include "occlusion/GpuMethod.h"
#include "occlusion/texturemask/SunMapSum.h"
#include "scene/CameraMath.h"

namespace flarekit::occlusion {

namespace {
class TextureMaskScreenMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto layout = sunMapLayout("circle", 1, true);
        if (!layout) return layout.error();
        auto sum = SunMapSum::create(std::move(*layout));
        if (!sum) return sum.error();
        auto fromDepth = FrameDepthProgram::link(
            {{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
             {GL_FRAGMENT_SHADER, "sunmap_from_depth.frag", shaders::sunmap_from_depth_frag}});
        if (!fromDepth) return fromDepth.error();
        return std::unique_ptr<GpuVisibility>(
            new TextureMaskScreenMethod(std::move(*sum), std::move(*fromDepth)));
    }
    std::string name() const override { return "texture-mask-screen"; }
    int latencyFrames() const override { return 0; }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        const int n = m_sum.size();
        const GLuint p = m_fromDepth.forFrame(renderer);
        setSunDiscUniforms(p, sunDiscView(view));  // the main camera, for the projection
        const CameraBasis map = cameraBasis(sunCamera(view));
        gl::setUniform(p, "mapRight", map.right);
        gl::setUniform(p, "mapUp", map.up);
        gl::setUniform(p, "mapForward", map.forward);
        glProgramUniform1f(p, gl::uniformLocation(p, "mapTanHalf"),
                           float(std::tan(view.sun.angularRadiusDeg * std::numbers::pi / 180.0)));
        glProgramUniform1f(p, gl::uniformLocation(p, "mapSize"), float(n));
        glBindFramebuffer(GL_FRAMEBUFFER, m_sum.sunMapFramebuffer());
        glViewport(0, 0, n, n);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        m_fromDepth.bindDepth(renderer);
        glBindVertexArray(m_vao.get());
        glUseProgram(p);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (Status s = m_sum.sumInto(coverageName()); !s) return s;
        markPublished();
        return Ok{};
    }
    std::vector<MethodView> views() const override { return m_sum.views(); }

  private:
    TextureMaskScreenMethod(SunMapSum sum, FrameDepthProgram fromDepth)
        : m_sum(std::move(sum)), m_fromDepth(std::move(fromDepth)) {
        m_vao = gl::makeVertexArray();
    }
    SunMapSum m_sum;
    FrameDepthProgram m_fromDepth;
    gl::VertexArray m_vao;
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeTextureMaskScreenMethod() {
    return TextureMaskScreenMethod::create();
}

}  // namespace flarekit::occlusion
