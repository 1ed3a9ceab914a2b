// SPDX-License-Identifier: Apache-2.0
// `readback`: the seed's "lock" method. After the scene pass, glReadPixels copies the depth
// under the sun's disc to the CPU, which must wait for the GPU to finish the frame first: the
// stall the GPG2 article measures. The coverage is computed on the CPU and published. With a
// multisampled frame it reads the per-pixel sky fraction of the depth samples instead (one
// more small pass), so occluder edges count to the sample.
#include <vector>

#include "occlusion/GpuMethod.h"
#include "occlusion/SkyFraction.h"
#include "occlusion/readback/DepthCoverage.h"
#include "scene/SceneTargets.h"

namespace flarekit::occlusion {

namespace {
class ReadbackMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto sky = SkyFraction::create();
        if (!sky) return sky.error();
        return std::unique_ptr<GpuVisibility>(new ReadbackMethod(std::move(*sky)));
    }
    std::string name() const override { return "readback"; }
    int latencyFrames() const override { return 0; }
    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        const SunDiscView v = sunDiscView(view);
        if (v.empty()) {
            publish(0.0);  // nothing of the disc on screen: a screen-space method sees no sun
            return Ok{};
        }
        const int w = v.x1 - v.x0, h = v.y1 - v.y0;
        m_depth.resize(std::size_t(w) * std::size_t(h));
        const bool multisampled = renderer.msaaSamples() > 1;
        GLuint source = sceneTargets(renderer).framebuffer;
        if (multisampled) {
            auto sky = m_sky.update(v, renderer);
            if (!sky) return sky.error();
            source = *sky;
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(v.x0, v.y0, w, h, multisampled ? GL_RED : GL_DEPTH_COMPONENT, GL_FLOAT,
                     m_depth.data());  // waits
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        if (Status s = gl::checkError("readback: glReadPixels"); !s) return s;
        publish(multisampled ? coverageFromSkyFraction(v, m_depth.data(), v.x0, v.y0, w, h)
                             : coverageFromDepth(v, m_depth.data(), v.x0, v.y0, w, h));
        return Ok{};
    }

  private:
    explicit ReadbackMethod(SkyFraction sky) : m_sky(std::move(sky)) {}
    SkyFraction m_sky;
    std::vector<float> m_depth;  // depth, or sky fractions with MSAA
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeReadbackMethod() {
    return ReadbackMethod::create();
}

}  // namespace flarekit::occlusion
