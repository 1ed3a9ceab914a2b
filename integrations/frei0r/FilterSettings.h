// SPDX-License-Identifier: Apache-2.0
// The frei0r filter's parameters: one table, in frei0r's parameter order, that feeds the
// plug-in's f0r_get_param_info, the clamping of what a host sets, the MLT metadata (the YAML
// Kdenlive and Shotcut list the effect from) and docs/hosts.md.
#pragma once

#include <string>
#include <string_view>

#include "HostFlare.h"
#include "flarekit/Flare.h"
#include "flarekit/Param.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit::frei0r {

using FilterMode = host::FlareMode;

//! Where the light is in each frame.
enum class LightSource {
    Track,     //!< found and followed through the clip by the shot tracker (as the CLI does)
    Auto,      //!< found in each frame on its own (sprite: every light the finder keeps)
    Position,  //!< the x and y parameters, which the host can keyframe
};
inline constexpr std::string_view kLightSourceNames[] = {"track", "auto", "position"};

struct FilterSettings {
    FilterMode mode = FilterMode::Sprite;
    std::string preset;  //!< a shipped preset (or lens) name or a JSON file; empty: the mode's
    LightSource light = LightSource::Track;
    double x = 0.5, y = 0.5;  //!< LightSource::Position: fractions of the frame's width, height
    float intensity = 1.f;
    double threshold = 0;  //!< 0: the preset's (or light finder's) own
    double fps = 24;       //!< the clip's frame rate: how far back the tracker looks
};

namespace detail {
// The library's own descriptions of the parameters the filter passes on (range, unit, help); a
// key that is not in its table does not compile.
inline constexpr const Param<ApplyOptions>& kIntensity =
    *findParam<ApplyOptions>(kApplyParams, "intensity");
inline constexpr const Param<ShotOptions>& kFps = *findParam<ShotOptions>(kShotParams, "fps");
}  // namespace detail

//! In frei0r's order; a host addresses them by name (ffmpeg, MLT) or by index.
//! Numbers are in the unit of the library's own parameter, not frei0r's customary 0-1 range:
//! ffmpeg and melt pass them through as typed, and the MLT metadata states each range.
inline constexpr Param<FilterSettings> kFilterNumberParams[] = {
    // Up to 2 frame widths outside the frame: a light's ghosts still cross it from there.
    param<&FilterSettings::x>("x", -2, 3, "of the width",
                              "light=position: the light's x, 0 the left edge, 1 the right"),
    param<&FilterSettings::y>("y", -2, 3, "of the height",
                              "light=position: the light's y, 0 the top edge, 1 the bottom"),
    param<&FilterSettings::intensity>("intensity", detail::kIntensity.min, detail::kIntensity.max,
                                      detail::kIntensity.unit, detail::kIntensity.help),
    // Up to 10^6 linear: past any light a video frame encodes (8-bit white is 1).
    param<&FilterSettings::threshold>(
        "threshold", 0, 1e6, "linear",
        "a light's smallest linear luminance (sprite and lens: the light finder's; postfx: the "
        "chain's bright-pass); 0: the preset's own"),
    param<&FilterSettings::fps>("fps", detail::kFps.min, detail::kFps.max, detail::kFps.unit,
                                "light=track: the clip's frame rate (the tracker looks back half "
                                "a second, as flarekit apply --fps does)"),
};
inline constexpr Param<FilterSettings> kFilterChoiceParams[] = {
    choice<&FilterSettings::mode>("mode", host::kFlareModeNames,
                                  "sprite: a sprite preset; postfx: the post-process chain (the "
                                  "frame's lights expanded as postfx --expand-highlights does); "
                                  "lens: a lens prescription's traced ghosts"),
    choice<&FilterSettings::light>("light", kLightSourceNames,
                                   "track: found and followed through the clip; auto: found in "
                                   "each frame; position: the x and y parameters"),
};
inline constexpr TextParam<FilterSettings> kFilterTextParams[] = {
    text<&FilterSettings::preset>(
        "preset",
        "a shipped preset name (postfx: a post-process preset, lens: a lens) or a JSON file; "
        "empty: tanczos-classic, photo or asahi-takumar-50"),
};

//! One frei0r parameter: a string (a choice or text) or a double.
struct FilterParam {
    std::string_view name;
    bool isString = false;
    const Param<FilterSettings>* number = nullptr;    //!< a number or a choice
    const TextParam<FilterSettings>* text = nullptr;  //!< the preset
    std::string_view help() const { return number ? number->help : text->help; }
};
//! frei0r's order: mode, preset, light, x, y, intensity, threshold, fps.
inline const FilterParam kFilterParams[] = {
    {"mode", true, &kFilterChoiceParams[0], nullptr},
    {"preset", true, nullptr, &kFilterTextParams[0]},
    {"light", true, &kFilterChoiceParams[1], nullptr},
    {"x", false, &kFilterNumberParams[0], nullptr},
    {"y", false, &kFilterNumberParams[1], nullptr},
    {"intensity", false, &kFilterNumberParams[2], nullptr},
    {"threshold", false, &kFilterNumberParams[3], nullptr},
    {"fps", false, &kFilterNumberParams[4], nullptr},
};
inline constexpr int kFilterParamCount = 8;

//! A host's value for a number: clamped to its range; NaN keeps the current value.
void setNumber(FilterSettings& settings, const Param<FilterSettings>& param, double value);
//! A host's text for a choice: one of its names, else an error naming the allowed ones.
Status setChoice(FilterSettings& settings, const Param<FilterSettings>& param,
                 std::string_view value);
//! The current value as the host reads it back.
std::string choiceName(const FilterSettings& settings, const Param<FilterSettings>& param);

//! The MLT service metadata (schema 0.3 YAML) of the filter: what Kdenlive and Shotcut list.
std::string mltMetadata();
//! The parameters as a Markdown table (docs/hosts.md).
std::string markdownTable();

}  // namespace flarekit::frei0r
