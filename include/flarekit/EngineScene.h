// flarekit's own scenes through the engine API (flarekit.h): a Scene's lights as fk_light
// records and a SceneRenderer's last frame as an fk_frame, so `flarekit lights`, `visibility
// --method compute` and the tests measure scene files exactly as an application would.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "flarekit/Render.h"
#include "flarekit/Scene.h"
#include "flarekit/flarekit.h"

namespace flarekit {

//! Every light of sceneLights(scene), in order; `presetId` turns a preset name into an id
//! (-1 for none; a light with preset "" gets -1 without asking).
std::vector<fk_light> engineLights(const Scene& scene,
                                   const std::function<int(const std::string&)>& presetId);

//! The frame `renderer` last drew for `scene`: its depth (the multisampled one with MSAA),
//! gluLookAt / gluPerspective matrices, the whole target as viewport, classic [-1, 1] depth.
fk_frame engineFrame(const Scene& scene, const SceneRenderer& renderer, float dtSeconds = 0);

//! The renderer's transmittance target (the translucent objects' share of light let through
//! per pixel), or 0 when its scene has no translucent object.
unsigned engineTransmittance(const SceneRenderer& renderer);

//! The renderer's HDR colour target (a framebuffer name), where fk_engine_draw adds flares.
unsigned engineColorFramebuffer(const SceneRenderer& renderer);

}  // namespace flarekit
