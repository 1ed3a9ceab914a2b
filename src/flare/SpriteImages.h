// SPDX-License-Identifier: Apache-2.0
// A preset's elements as sprite images for frames of one height: each element rendered once on
// the CPU (renderElement, the kernels of renderFlare) at its size in pixels, Tanczos's sprite
// textures, with where and how large each is drawn. No GL: the engine API uploads them as
// textures (ElementSprites.h), the instance-data API hands them to any renderer.
#pragma once

#include <vector>

#include "flarekit/Flare.h"

namespace flarekit {

//! renderFlare skips elements below half a pixel in radius (FlareRenderer.cpp); so do sprites.
inline constexpr float kMinSpriteRadiusPx = 0.5f;

struct SpriteImage {
    float t;             //!< position on the flare vector
    float halfW, halfH;  //!< quad half size, frame pixels
    BlendMode blend;
    bool edgeStreak;  //!< placed by edgeStreakPlacement instead of on the flare vector
    float reach;      //!< edge streak: its reach (ElementParams::reach)
    Image image;      //!< RGBA premultiplied, top row first, with a clear border
};

//! The sprites of `preset` for frames `height` pixels tall (element sizes are fractions of the
//! height); elements under half a pixel or without intensity get none.
std::vector<SpriteImage> renderSpriteImages(const Preset& preset, int height);

}  // namespace flarekit
