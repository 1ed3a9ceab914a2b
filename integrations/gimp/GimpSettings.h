// SPDX-License-Identifier: Apache-2.0
// The GIMP plug-in's settings: what its dialog edits, what GIMP keeps between runs (a plain
// struct, which gimp_set_data stores as bytes) and the procedure's arguments, described once.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

#include "HostFlare.h"
#include "flarekit/Param.h"
#include "flarekit/job/ApplyJob.h"

namespace flarekit::gimp {

inline constexpr const char* kProcedure = "plug-in-flarekit-lens-flare";
inline constexpr const char* kBinary = "flarekit-gimp";

//! Kept as bytes by GIMP between runs: fixed size, no pointers.
struct Settings {
    int mode = 0;           //!< host::FlareMode
    char preset[512] = {};  //!< a shipped name or a JSON file; empty: the mode's default
    int findLight = 1;      //!< 1: the light found in the image; 0: at x, y
    double x = 0, y = 0;    //!< the light in image pixels from the top-left (may be off-canvas)
    double intensity = 1;
    double threshold = 0;  //!< 0: the preset's own
    int newLayer = 1;      //!< 1: the flare as a new Addition layer above; 0: onto the layer

    host::FlareMode flareMode() const { return host::FlareMode(mode); }
    std::string presetName() const { return std::string(preset, ::strnlen(preset, sizeof preset)); }
    void setPreset(std::string_view name);
};

//! The numbers' ranges: intensity is the library's own parameter; a threshold up to 10^6
//! linear is past any light a photograph or render holds.
inline constexpr const Param<ApplyOptions>& kIntensityParam =
    *findParam<ApplyOptions>(kApplyParams, "intensity");
inline constexpr double kIntensityMin = kIntensityParam.min;
inline constexpr double kIntensityMax = kIntensityParam.max;
inline constexpr double kThresholdMax = 1e6;

//! One argument of the procedure after run-mode, image and drawable.
struct ProcedureArg {
    enum class Type { String, Int, Float } type;
    std::string_view name, help;
};
inline constexpr ProcedureArg kProcedureArgs[] = {
    {ProcedureArg::Type::String, "mode",
     "sprite (a sprite preset), postfx (the post-process chain) or lens (a lens prescription's "
     "traced ghosts)"},
    {ProcedureArg::Type::String, "preset",
     "a shipped sprite preset, post-process preset or lens (by mode), or a JSON file; empty: "
     "tanczos-classic, photo or asahi-takumar-50"},
    {ProcedureArg::Type::Int, "find-light",
     "TRUE: the light found in the image as flarekit apply --light auto finds it; FALSE: at "
     "light-x, light-y"},
    {ProcedureArg::Type::Float, "light-x", "the light's x in image pixels (off-canvas allowed)"},
    {ProcedureArg::Type::Float, "light-y", "the light's y in image pixels (off-canvas allowed)"},
    {ProcedureArg::Type::Float, "intensity", "flare brightness multiplier (0 to 1000)"},
    {ProcedureArg::Type::Float, "threshold",
     "a light's smallest linear luminance (0: the preset's or light finder's own)"},
    {ProcedureArg::Type::Int, "new-layer",
     "TRUE: the flare as a new layer in Addition mode above the drawable (mask it, fade it); "
     "FALSE: drawn onto the drawable"},
};
inline constexpr int kProcedureArgCount = int(sizeof kProcedureArgs / sizeof kProcedureArgs[0]);

//! The procedure's arguments as a Markdown table (docs/hosts.md; flarekit-gimp --markdown).
std::string markdownTable();

//! The settings checked: an error names the argument.
Status checkSettings(const Settings& settings);

}  // namespace flarekit::gimp
