// SPDX-License-Identifier: Apache-2.0
// The one GPU sprite-flare draw: a preset's element sprites instanced over the lights of a light
// buffer (light_flare.vert places and weighs each instance from the coverage texture). The
// engine API draws every light of a call through it; GpuSpriteFlare (the frame pipeline's
// sun) draws one light through it.
#pragma once

#include <span>

#include "engine/EnginePrograms.h"
#include "flare/ElementSprites.h"

namespace flarekit::engine {

//! What one draw reads besides the GL state its caller binds: the framebuffer and viewport,
//! the lights at kLightsBinding, the coverage texture at kCoverageUnit, the program's vertex
//! array, and (unless elementBlends) additive blending.
struct FlareDraw {
    const fk_frame* frame = nullptr;  //!< matrices and viewport the lights project through
    int view = 0;                     //!< the coverage texture's row
    int presetId = 0;                 //!< instances whose light has another preset collapse
    int lightCount = 0;               //!< instances
    int coverageChannel = 0;          //!< the channel of texel (light, view) weighing a light
    float guardBand = 0;              //!< with fadeAtEdges: the fade's width, shorter sides
    //! Fade a light near the viewport's edge here (the engine: its coverage is a measurement).
    //! GpuSpriteFlare's weight is the temporal filter's, which has the fade in it already.
    bool fadeAtEdges = true;
    //! Composite each element with its own blend mode (GpuSpriteFlare, as renderFlare does);
    //! otherwise every element adds over the caller's blend state (the engine, into the
    //! application's linear HDR colour).
    bool elementBlends = false;
};

//! One glDrawArraysInstanced per sprite of the preset.
void drawFlareElements(const FlareProgram& program, std::span<const ElementSprite> sprites,
                       const FlareDraw& draw);

}  // namespace flarekit::engine
