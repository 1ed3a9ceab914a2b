// SPDX-License-Identifier: Apache-2.0
#include <cstdio>

#include "flarekit/gl/GpuLens.h"
#include "flarekit/gl/HeadlessGl.h"
#include "flarekit/gl/LensBackend.h"

namespace flarekit::gl {

namespace {
class GlBackend final : public LensBackend {
  public:
    std::string name() const override { return "gl"; }
    bool usesGl() const override { return true; }
    Result<LensFlareLayers> render(const Lens& lens, int width, int height,
                                   const std::vector<LensLight>& lights,
                                   const LensRenderOptions& options, const std::string& in,
                                   bool verbose, const JobEvents& events) const override {
        auto context = createQuietHeadlessGl();
        if (!context) return context.error();
        if (Status s = checkGlFrame(width, height, 1, in + ": image"); !s) return s.error();
        LensGlTimes times;
        auto layers = renderLensFlareGl(lens, width, height, lights, options, &times);
        if (layers && verbose) {
            char line[300];
            std::snprintf(line, sizeof line, "OpenGL: %s: ghosts %.2f GPU ms, read-back %.2f ms",
                          (*context)->renderer().c_str(), times.ghostsGpuMs, times.readbackMs);
            events.say(line);
        }
        return layers;
    }
};
}  // namespace

std::shared_ptr<const LensBackend> glLensBackend() {
    static const auto backend = std::make_shared<const GlBackend>();
    return backend;
}

}  // namespace flarekit::gl
