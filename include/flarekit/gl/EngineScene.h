// SPDX-License-Identifier: Apache-2.0
// flarekit's own scenes through the engine API (flarekit.h): a Scene's lights as fk_light
// records and a SceneRenderer's last frame as an fk_frame, so `flarekit lights`, `visibility
// --method compute` and the tests measure scene files exactly as an application would.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/Scene.h"
#include "flarekit/flarekit.h"
#include "flarekit/gl/Render.h"

namespace flarekit {

//! The engine API's visibility methods (fk_engine_create's `method`).
inline constexpr std::string_view kEngineMethodNames[] = {"compute", "texture-mask"};

//! How the engine measures each light (fk_engine_set_samples), described once for the engine,
//! the CLI's flags and the docs.
struct EngineMeasureSettings {
    //! Directions per side cast per light: 32^2 = 1,024 jittered strata give a standard error
    //! near sqrt(2 x 32) / 1024 = 0.008 for an edge across the disc, inside the 0.02 the API is
    //! held to against the ray caster.
    int samplesPerSide = 32;
    //! Lights whose disc covers fewer depth samples than this (pi r^2 x MSAA samples, r its
    //! radius in pixels) are measured from a sun-map tile the occluder callback draws, when one
    //! is set. A depth buffer places an edge only to its sample grid, which is a large share of
    //! a small disc: measured on 256 lamps of 0.5-40 px radius (docs/engine-api.md), 1x depth
    //! was off by 0.26 at 1 px, 0.05 at 5 px and up to 0.018 at 15 px; 1,024 samples (18 px
    //! at 1x, 9 px at 4x MSAA) keeps every light inside 0.02.
    int tileBelowSamples = 1024;
};

inline constexpr Param<EngineMeasureSettings> kEngineMeasureParams[] = {
    // 64^2 = 4,096 directions, 16 per thread of a light's 256-thread work group
    // (light_coverage.comp): a light's pass stays one dispatch's small share.
    param<&EngineMeasureSettings::samplesPerSide>(
        "samples", 1, 64, "",
        "directions per side cast per light (N^2 rays; 32: error near 0.008)"),
    // 2^20: a light wider than the largest frame's depth (a 4K frame at 8x MSAA is 2^26
    // samples; a disc of 2^20 already spans 577 px at 1x, where the depth is exact enough).
    param<&EngineMeasureSettings::tileBelowSamples>(
        "tile-below", 0, 1 << 20, "samples",
        "lights covering fewer depth samples are measured from sun-map tiles the occluder "
        "callback draws (0: never)"),
};

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

//! A scene's objects as the texture-mask occluder callback draws them (fk_occluder_callback):
//! opaque ones black, translucent ones multiplying the tile by 1 - opacity (spheres and boxes
//! by their front faces, so once each, as the ray caster counts them). A GL context must be
//! current while it lives.
class SceneOccluders {
  public:
    static Result<std::unique_ptr<SceneOccluders>> create(const Scene& scene);
    ~SceneOccluders();
    //! The callback itself; `user` is the SceneOccluders.
    static void draw(void* user, int view, int light, const float viewProjection[16],
                     unsigned framebuffer, const int viewport[4]);

  private:
    struct Impl;
    explicit SceneOccluders(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit
