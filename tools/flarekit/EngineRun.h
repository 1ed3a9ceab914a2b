// SPDX-License-Identifier: Apache-2.0
// `flarekit lights` and `visibility --method compute`: the library's runEngineScene
// (flarekit/gl/EngineRun.h) and the two ways its per-light numbers are printed.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/EngineRun.h"

namespace flarekit::cli {

//! runEngineScene, or (built without GL) the one-line refusal.
Result<EngineRun> runEngine(const Scene& scene, const EngineRunOptions& options);

//! Every light's coverage as `visibility --json` and `lights --json` print it (a contract):
//! `[{"coverage": c, "in_frame": f}, ...]` in scene order.
std::string lightsJson(const std::vector<LightVisibility>& lights);
//! The same as lines: "  light i: coverage c, p% in frame".
void printLights(const std::vector<LightVisibility>& lights);

}  // namespace flarekit::cli
