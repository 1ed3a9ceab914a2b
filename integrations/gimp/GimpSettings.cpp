// SPDX-License-Identifier: Apache-2.0
#include "GimpSettings.h"

#include <cmath>
#include <cstring>

#include "flarekit/ParamText.h"

namespace flarekit::gimp {

void Settings::setPreset(std::string_view name) {
    std::memset(preset, 0, sizeof preset);
    std::memcpy(preset, name.data(), std::min(name.size(), sizeof preset - 1));
}

Status checkSettings(const Settings& s) {
    const std::size_t modes = std::size(host::kFlareModeNames);
    if (s.mode < 0 || std::size_t(s.mode) >= modes)
        return invalidInput("mode: expected sprite, postfx or lens");
    if (!s.findLight) {
        if (Status st = checkLightCoordinates(Point{float(s.x), float(s.y)}, "light-x, light-y");
            !st)
            return st;
    }
    if (!std::isfinite(s.intensity) || s.intensity < kIntensityMin || s.intensity > kIntensityMax)
        return invalidInput("intensity: expected a number in " +
                            formatParamRange(kIntensityMin, kIntensityMax) + ", got " +
                            std::to_string(s.intensity));
    if (!std::isfinite(s.threshold) || s.threshold < 0 || s.threshold > kThresholdMax)
        return invalidInput("threshold: expected a number in " +
                            formatParamRange(0, kThresholdMax) + ", got " +
                            std::to_string(s.threshold));
    return Ok{};
}

std::string markdownTable() {
    std::string t =
        "| # | argument | type | what it is |\n|---|---|---|---|\n"
        "| 0 | `run-mode` | INT32 | RUN-INTERACTIVE, RUN-NONINTERACTIVE or "
        "RUN-WITH-LAST-VALS |\n| 1 | `image` | IMAGE | the image |\n"
        "| 2 | `drawable` | DRAWABLE | the layer to flare |\n";
    int index = 3;
    for (const ProcedureArg& a : kProcedureArgs) {
        const char* type = a.type == ProcedureArg::Type::String ? "STRING"
                           : a.type == ProcedureArg::Type::Int  ? "INT32"
                                                                : "FLOAT";
        t += "| " + std::to_string(index++) + " | `" + std::string(a.name) + "` | " + type + " | " +
             std::string(a.help) + " |\n";
    }
    return t;
}

}  // namespace flarekit::gimp
