// SPDX-License-Identifier: Apache-2.0
// One still of a scene file through the frame pipeline: flarekit's renderer draws the frame,
// a visibility method measures the sun and the sprite flare is drawn at it, scaled by the
// coverage. `raycast` measures on the CPU at its ground-truth sample count; a GPU method's
// flare reads its coverage on the GPU. Behind `flarekit render`; it makes its own headless
// context.
#pragma once

#include <string>

#include "flarekit/Flare.h"
#include "flarekit/Result.h"
#include "flarekit/gl/FramePipeline.h"
#include "flarekit/gl/Render.h"

namespace flarekit::gl {

struct SceneStillOptions {
    std::string scene;                          //!< scene JSON file
    std::string preset = kDefaultSpritePreset;  //!< sprite preset: shipped name or JSON file
    std::string method = "raycast";             //!< raycast or a GPU visibility method
    std::string variant = "circle";  //!< texture-mask sampling (kTextureMaskVariantNames)
    RenderOptions render;            //!< MSAA, shadows
    bool flare = true;               //!< false: the frame only
};

struct SceneStill {
    PipelineFrame frame;             //!< linear HDR, the coverage and where the sun is
    std::string renderer, platform;  //!< GL_RENDERER and the EGL platform it ran on
};

//! The frame pipeline's settings of a still: no temporal filter, linear HDR out, raycast at its
//! ground-truth sample count (what `flarekit render` and the studio's scene view run).
FramePipelineSettings sceneStillSettings(const SceneStillOptions& options);

//! Loads the scene and the preset, checks the work and the frame against the GL limits, then
//! renders one still (no temporal filter, linear HDR out). Errors name the file or the option
//! by its table name.
Result<SceneStill> renderSceneStill(const SceneStillOptions& options);

}  // namespace flarekit::gl
