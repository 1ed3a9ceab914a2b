// The GPU method factory: contract names to implementations (one folder each).
#include "flarekit/GpuVisibility.h"

#include <algorithm>

#include "occlusion/GpuMethod.h"

namespace flarekit {

namespace occlusion {
Result<std::unique_ptr<GpuVisibility>> makeReadbackMethod();
Result<std::unique_ptr<GpuVisibility>> makePboMethod(int ring);
Result<std::unique_ptr<GpuVisibility>> makeQueryMethod();
Result<std::unique_ptr<GpuVisibility>> makeComputeMethod();
Result<std::unique_ptr<GpuVisibility>> makeTextureMaskMethod(const Scene& world, const std::string& variant);
Result<std::unique_ptr<GpuVisibility>> makeTextureMaskScreenMethod();
Result<std::unique_ptr<GpuVisibility>> makeBurnoutMethod();
}  // namespace occlusion

namespace {

using MakeMethod = Result<std::unique_ptr<GpuVisibility>> (*)(const Scene& world, const GpuVisibilityOptions& options);

//! The one registry of GPU methods: the contract name and its factory. The name list, --help,
//! validation and createGpuVisibility all read it.
struct MethodEntry {
    const char* name;
    MakeMethod make;
};

Result<std::unique_ptr<GpuVisibility>> makePbo(const Scene&, const GpuVisibilityOptions& options) {
    if (options.pboRing < 1 || options.pboRing > 16) {
        return invalidInput("pbo ring: expected 1 to 16 buffers, got " + std::to_string(options.pboRing));
    }
    return occlusion::makePboMethod(options.pboRing);
}

const MethodEntry kMethods[] = {
    {"readback", [](const Scene&, const GpuVisibilityOptions&) { return occlusion::makeReadbackMethod(); }},
    {"pbo", makePbo},
    {"query", [](const Scene&, const GpuVisibilityOptions&) { return occlusion::makeQueryMethod(); }},
    {"texture-mask",
     [](const Scene& world, const GpuVisibilityOptions& o) { return occlusion::makeTextureMaskMethod(world, o.textureMaskVariant); }},
    {"texture-mask-screen", [](const Scene&, const GpuVisibilityOptions&) { return occlusion::makeTextureMaskScreenMethod(); }},
    {"burnout", [](const Scene&, const GpuVisibilityOptions&) { return occlusion::makeBurnoutMethod(); }},
    {"compute", [](const Scene&, const GpuVisibilityOptions&) { return occlusion::makeComputeMethod(); }},
};

}  // namespace

const std::vector<std::string>& gpuVisibilityMethods() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const MethodEntry& m : kMethods) out.emplace_back(m.name);
        return out;
    }();
    return names;
}

Result<double> measureStillFrame(GpuVisibility& method, SceneRenderer& renderer, const Scene& view, int maxFrames,
                                 int* frames) {
    for (int frame = 0; frame < maxFrames; ++frame) {
        if (Status s = renderer.draw(view); !s) return s.error();
        if (Status s = method.measure(view, renderer); !s) return s.error();
        // The newest result must come from a measure() of this call, not from an earlier view
        // the method saw: its latency (frames behind the newest measure) tells which.
        const std::optional<double> coverage = method.latestCoverage();
        if (coverage && method.latencyFrames() <= frame) {
            if (frames) *frames = frame;
            return *coverage;
        }
    }
    return internalError(method.name() + ": no result after " + std::to_string(maxFrames) + " frames");
}

bool isGpuVisibilityMethod(const std::string& name) {
    const auto& names = gpuVisibilityMethods();
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string visibilityMethodList() {
    std::string list = "raycast";
    for (const std::string& n : gpuVisibilityMethods()) list += " " + n;
    return list;
}

Result<std::unique_ptr<GpuVisibility>> createGpuVisibility(const std::string& method, const Scene& world,
                                                           const GpuVisibilityOptions& options) {
    for (const MethodEntry& m : kMethods) {
        if (method == m.name) return m.make(world, options);
    }
    std::string list;
    for (const std::string& n : gpuVisibilityMethods()) list += (list.empty() ? "" : " ") + n;
    return invalidInput("method: '" + method + "' is not a GPU visibility method; expected one of: " + list);
}

}  // namespace flarekit
