// SPDX-License-Identifier: Apache-2.0
// The colour transform of a job (flarekit/job/Job.h) through OpenColorIO: the input converted
// from its colour space to the config's scene_linear (flarekit's working space, linear Rec.709
// in the shipped config), the result from there to the output's. A separate target
// (flarekit::ocio), so that a program without colour management links no OpenColorIO.
#pragma once

#include <memory>
#include <string>

#include "flarekit/Param.h"
#include "flarekit/Result.h"
#include "flarekit/job/Job.h"

namespace flarekit {

struct OcioSettings {
    std::string in, out;  //!< the input's and the output's colour space; empty: flarekit's default
    std::string config;   //!< the config file; empty: $OCIO, else the shipped flarekit.ocio
    bool enabled() const { return !in.empty() || !out.empty(); }
};
inline constexpr TextParam<OcioSettings> kOcioTextParams[] = {
    text<&OcioSettings::in>("colorspace_in",
                            "the input's colour space in the OCIO config (default: sRGB for "
                            "8/16-bit files, scene-linear Rec.709 for float files)"),
    text<&OcioSettings::out>(
        "colorspace_out",
        "the output's colour space in the OCIO config (default: as the input's kind)"),
    text<&OcioSettings::config>("ocio_config",
                                "OpenColorIO config file (default: $OCIO, else the shipped "
                                "presets/ocio/flarekit.ocio; an ACES config works too)"),
};

//! The config and both colour spaces checked: an unknown name is one line listing the config's
//! colour spaces. Null when neither space is given (flarekit's defaults apply). Building the
//! processors once; applying them is thread-safe, as a shot's parallel frames need.
Result<std::shared_ptr<const ColorTransform>> createOcioTransform(const OcioSettings& settings);

}  // namespace flarekit
