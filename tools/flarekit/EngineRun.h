// SPDX-License-Identifier: Apache-2.0
// A scene file through the engine API, as an application would use it: flarekit's renderer
// draws the frame, the C API measures every light on its depth (and transmittance) in one
// batched pass and, when asked, adds every light's flare. Shared by `flarekit lights` and
// `flarekit visibility --method compute`.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/EngineScene.h"
#include "flarekit/gl/Render.h"

namespace flarekit::cli {

struct EngineRunOptions {
    std::string source;  //!< the scene file, for messages
    std::string method = "compute";
    RenderOptions render;
    int samplesPerSide = EngineMeasureSettings{}.samplesPerSide;
    bool flares = true;  //!< draw the flares and read the frame back
};

struct EngineRun {
    std::vector<LightVisibility> lights;  //!< raw coverage and in-frame share, scene order
    Image image;                          //!< linear HDR frame with the flares (flares only)
    double cpuMs = 0;                     //!< wall time inside fk_engine_occlusion + fk_engine_draw
    double occlusionGpuMs = 0, drawGpuMs = 0;  //!< timer queries around the two calls
    std::string renderer;                      //!< GL_RENDERER
};

Result<EngineRun> runEngine(const Scene& scene, const EngineRunOptions& options);

//! Every light's coverage as `visibility --json` and `lights --json` print it (a contract):
//! `[{"coverage": c, "in_frame": f}, ...]` in scene order.
std::string lightsJson(const std::vector<LightVisibility>& lights);
//! The same as lines: "  light i: coverage c, p% in frame".
void printLights(const std::vector<LightVisibility>& lights);

}  // namespace flarekit::cli
