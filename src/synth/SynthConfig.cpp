// SPDX-License-Identifier: Apache-2.0
#include <filesystem>

#include "core/JsonText.h"
#include "core/ParamJson.h"
#include "flarekit/Synth.h"

namespace flarekit {

Result<SynthConfig> parseSynthConfig(const std::string& jsonText, const std::string& source) {
    auto parsed = parseJsonText(jsonText, source);
    if (!parsed) return parsed.error();
    const nlohmann::json& v = *parsed;
    SynthConfig config;
    const JsonPlace place(source);
    if (auto error = readParams<SynthConfig>(v, kSynthParams, config, place, {"backgrounds"}))
        return *error;
    if (v.contains("backgrounds")) {
        if (!v["backgrounds"].is_string())
            return (place / "backgrounds")
                .fail("expected a folder name, got " + jsonExcerpt(v["backgrounds"]));
        config.backgrounds = v["backgrounds"].get<std::string>();
    }
    if (Status s = checkSynthConfig(config); !s)
        return invalidInput(source + ": " + s.error().message);
    return config;
}

Status checkSynthConfig(const SynthConfig& c) {
    if (Status s = validateParams<SynthConfig>(c, kSynthParams, ""); !s) return s;
    const struct {
        double lo, hi;
        const char *low, *high;
    } pairs[] = {{double(c.lightsMin), double(c.lightsMax), "lights_min", "lights_max"},
                 {c.depthMin, c.depthMax, "depth_min", "depth_max"},
                 {c.intensityMin, c.intensityMax, "intensity_min", "intensity_max"},
                 {c.radiusMin, c.radiusMax, "radius_min", "radius_max"},
                 {c.exposureMin, c.exposureMax, "exposure_min", "exposure_max"},
                 {c.gammaMin, c.gammaMax, "gamma_min", "gamma_max"}};
    for (const auto& p : pairs)
        if (p.lo > p.hi)
            return invalidInput(std::string(p.high) + ": expected at least " + p.low + " (" +
                                formatParamNumber(p.lo) + "), got " + formatParamNumber(p.hi));
    if (c.jpegQuality > 0 && c.bits != 8)
        return invalidInput("jpeg_quality: JPEG holds 8-bit samples: give bits 8, got bits " +
                            std::to_string(c.bits));
    if (!(c.spriteWeight + c.postfxWeight + c.lensWeight > 0))
        return invalidInput("sprite, postfx, lens: expected a weight above 0 for one of them");
    if (!c.backgrounds.empty()) {
        std::error_code ec;
        if (!std::filesystem::is_directory(c.backgrounds, ec))
            return invalidInput("backgrounds: " + c.backgrounds + ": not a folder");
    }
    return Ok{};
}

std::string synthParameterReference() {
    const SynthConfig defaults;
    return "| key | default | range | unit | meaning |\n|---|---|---|---|---|\n" +
           markdownRows<SynthConfig>(
               kSynthParams, &defaults, [](const auto&) { return std::string(); },
               [](const auto&) { return std::string(); }) +
           "| `backgrounds` | \"\" (procedural) | a folder | | images the backgrounds are cropped "
           "from (8/16-bit decoded to linear) |\n";
}

std::string synthConfigJson(const SynthConfig& config) {
    nlohmann::json out = nlohmann::json::object();
    for (const Param<SynthConfig>& p : kSynthParams)
        out[std::string(p.key)] = paramJsonValue(p, p.get(config));
    out["backgrounds"] = config.backgrounds;
    return out.dump();
}

}  // namespace flarekit
