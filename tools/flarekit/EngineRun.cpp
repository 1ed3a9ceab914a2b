// SPDX-License-Identifier: Apache-2.0
#include "EngineRun.h"

#include <cstdio>

#include "Common.h"
#include "JsonLine.h"

namespace flarekit::cli {

std::string lightsJson(const std::vector<LightVisibility>& lights) {
    std::string out = "[";
    for (std::size_t i = 0; i < lights.size(); ++i) {
        JsonLine light;
        light.number("coverage", lights[i].coverage, 6).number("in_frame", lights[i].inFrame, 6);
        out += (i ? ", " : "") + light.str();
    }
    return out + "]";
}

void printLights(const std::vector<LightVisibility>& lights) {
    for (std::size_t i = 0; i < lights.size(); ++i)
        std::printf("  light %zu: coverage %.4f, %.1f%% in frame\n", i, lights[i].coverage,
                    100 * lights[i].inFrame);
}

Result<EngineRun> runEngine([[maybe_unused]] const Scene& scene, const EngineRunOptions& o) {
#if FLAREKIT_HAS_GL
    return runEngineScene(scene, o);
#else
    return builtWithoutGl(o.flares ? "lights" : "visibility --method " + o.method);
#endif
}

}  // namespace flarekit::cli
