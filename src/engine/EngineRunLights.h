// SPDX-License-Identifier: Apache-2.0
// The scene's lights as fk_light records for an engine of either backend, each preset they
// name loaded into it once (runEngineScene, and its Vulkan half).
#pragma once

#include <vector>

#include "flarekit/gl/EngineRun.h"

namespace flarekit {

//! Errors name `options.source` and the light whose preset failed (lights[i].preset).
Result<std::vector<fk_light>> sceneEngineLights(fk_engine* e, const Scene& scene,
                                                const EngineRunOptions& options);

}  // namespace flarekit
