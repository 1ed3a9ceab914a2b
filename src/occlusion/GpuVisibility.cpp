// SPDX-License-Identifier: Apache-2.0
// The GPU method factory: contract names to implementations (one folder each).
#include "flarekit/gl/GpuVisibility.h"
#include "gl/GlObjects.h"

#include <algorithm>

#include "occlusion/GpuMethod.h"
#include "occlusion/MethodRegistry.h"

namespace flarekit {

namespace occlusion {
Result<std::unique_ptr<GpuVisibility>> makeReadbackMethod();
Result<std::unique_ptr<GpuVisibility>> makePboMethod(int ring);
Result<std::unique_ptr<GpuVisibility>> makeQueryMethod();
Result<std::unique_ptr<GpuVisibility>> makeComputeMethod();
Result<std::unique_ptr<GpuVisibility>> makeTextureMaskMethod(const Scene& world,
                                                             const std::string& variant);
Result<std::unique_ptr<GpuVisibility>> makeTextureMaskScreenMethod();
Result<std::unique_ptr<GpuVisibility>> makeBurnoutMethod();
}  // namespace occlusion

namespace {

using MakeMethod = Result<std::unique_ptr<GpuVisibility>> (*)(const Scene& world,
                                                              const GpuVisibilityOptions& options);
using namespace occlusion;

// Adapters from the registry's one factory signature to each method's own.
Result<std::unique_ptr<GpuVisibility>> makeReadback(const Scene&, const GpuVisibilityOptions&) {
    return makeReadbackMethod();
}
Result<std::unique_ptr<GpuVisibility>> makePbo(const Scene&, const GpuVisibilityOptions& options) {
    if (options.pboRing < 1 || options.pboRing > 16) {
        return invalidInput("pbo ring: expected 1 to 16 buffers, got " +
                            std::to_string(options.pboRing));
    }
    return makePboMethod(options.pboRing);
}
Result<std::unique_ptr<GpuVisibility>> makeQuery(const Scene&, const GpuVisibilityOptions&) {
    return makeQueryMethod();
}
Result<std::unique_ptr<GpuVisibility>> makeTextureMask(const Scene& world,
                                                       const GpuVisibilityOptions& options) {
    return makeTextureMaskMethod(world, options.textureMaskVariant);
}
Result<std::unique_ptr<GpuVisibility>> makeTextureMaskScreen(const Scene&,
                                                             const GpuVisibilityOptions&) {
    return makeTextureMaskScreenMethod();
}
Result<std::unique_ptr<GpuVisibility>> makeBurnout(const Scene&, const GpuVisibilityOptions&) {
    return makeBurnoutMethod();
}
Result<std::unique_ptr<GpuVisibility>> makeCompute(const Scene&, const GpuVisibilityOptions&) {
    return makeComputeMethod();
}

struct MethodEntry {
    const char* name;
    MakeMethod make;
};
#define FLAREKIT_METHOD_ENTRY(name, factory) {name, factory},
const MethodEntry kMethods[] = {FLAREKIT_GPU_METHODS(FLAREKIT_METHOD_ENTRY)};
#undef FLAREKIT_METHOD_ENTRY

}  // namespace

Result<double> measureStillFrame(GpuVisibility& method, SceneRenderer& renderer, const Scene& view,
                                 int maxFrames, int* frames) {
    for (int frame = 0; frame < maxFrames; ++frame) {
        if (Status s = renderer.draw(view); !s) return s.error();
        if (Status s = method.measure(view, renderer); !s) return s.error();
        // The newest result must come from a measure() of this call, not from an earlier view
        // the method saw: its age (measures since the one it came from) tells which.
        const std::optional<double> coverage = method.latestCoverage();
        if (coverage && method.resultAge() <= frame) {
            if (frames) *frames = frame;
            return *coverage;
        }
    }
    return internalError(method.name() + ": no result after " + std::to_string(maxFrames) +
                         " frames");
}

Result<std::unique_ptr<GpuVisibility>> createGpuVisibility(const std::string& method,
                                                           const Scene& world,
                                                           const GpuVisibilityOptions& options) {
    if (Status s = gl::requireCurrentContext("createGpuVisibility"); !s) return s.error();
    for (const MethodEntry& m : kMethods) {
        if (method == m.name) return m.make(world, options);
    }
    std::string list;
    for (const std::string& n : gpuVisibilityMethods()) list += (list.empty() ? "" : " ") + n;
    return invalidInput("method: '" + method +
                        "' is not a GPU visibility method; expected one of: " + list);
}

}  // namespace flarekit
