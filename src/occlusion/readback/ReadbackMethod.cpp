// `readback`: the seed's "lock" method. After the scene pass, glReadPixels copies the depth
// under the sun's disc to the CPU, which must wait for the GPU to finish the frame first: the
// stall the GPG2 article measures. The coverage is computed on the CPU and published.
#include <vector>

#include "occlusion/GpuMethod.h"
#include "occlusion/readback/DepthCoverage.h"

namespace flarekit::occlusion {

namespace {
class ReadbackMethod final : public GpuMethod {
public:
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
        glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer.framebuffer());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(v.x0, v.y0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, m_depth.data());  // waits for the GPU
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        if (Status s = glStatus("readback: glReadPixels"); !s) return s;
        publish(coverageFromDepth(v, m_depth.data(), v.x0, v.y0, w, h));
        return Ok{};
    }

private:
    std::vector<float> m_depth;
};
}  // namespace

std::unique_ptr<GpuVisibility> makeReadbackMethod() { return std::make_unique<ReadbackMethod>(); }

}  // namespace flarekit::occlusion
