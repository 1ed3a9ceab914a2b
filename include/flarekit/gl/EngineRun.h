// SPDX-License-Identifier: Apache-2.0
// A scene file through the engine API, as an application would use it: flarekit's renderer
// draws the frame, the C API measures every light on its depth (and transmittance) in one
// batched pass and, when asked, adds every light's flare. Behind `flarekit lights` and
// `flarekit visibility --method compute|texture-mask`; it makes its own headless context.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/EngineScene.h"
#include "flarekit/gl/Render.h"

namespace flarekit {

struct EngineRunOptions {
    std::string source;  //!< the scene file, for messages
    std::string method = "compute";
    //! "gl", or "vulkan": the depth drawn again by a Vulkan host and every light measured and
    //! drawn through the Vulkan backend (compute only).
    std::string backend = "gl";
    RenderOptions render;
    EngineMeasureSettings measure;  //!< kEngineMeasureParams
    bool flares = true;             //!< draw the flares and read the frame back
};

struct EngineRun {
    std::vector<LightVisibility> lights;  //!< raw coverage and in-frame share, scene order
    Image image;                          //!< linear HDR frame with the flares (flares only)
    double cpuMs = 0;                     //!< wall time inside fk_engine_occlusion + fk_engine_draw
    double occlusionGpuMs = 0, drawGpuMs = 0;  //!< timer queries around the two calls
    std::string renderer;                      //!< GL_RENDERER
};

//! Renders `scene`, measures (and with `flares` draws) every light through the C API. Errors
//! name `options.source`; a light whose preset does not load names itself (lights[i].preset).
Result<EngineRun> runEngineScene(const Scene& scene, const EngineRunOptions& options);

}  // namespace flarekit
