// SPDX-License-Identifier: Apache-2.0
// The colour transform of a job (flarekit/job/Job.h) through OpenColorIO: the input converted
// from its colour space to the config's scene_linear (flarekit's working space, linear Rec.709
// in the shipped config), the result from there to the output's. A separate target
// (flarekit::ocio), so that a program without colour management links no OpenColorIO.
#pragma once

#include <memory>
#include <string>

#include "flarekit/Result.h"
#include "flarekit/job/Job.h"

namespace flarekit {

struct OcioSettings {
    std::string in, out;  //!< the input's and the output's colour space; empty: flarekit's default
    std::string config;   //!< the config file; empty: $OCIO, else the shipped flarekit.ocio
    bool enabled() const { return !in.empty() || !out.empty(); }
};

//! The config and both colour spaces checked: an unknown name is one line listing the config's
//! colour spaces. Null when neither space is given (flarekit's defaults apply). Building the
//! processors once; applying them is thread-safe, as a shot's parallel frames need.
Result<std::shared_ptr<const ColorTransform>> createOcioTransform(const OcioSettings& settings);

}  // namespace flarekit
