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

//! Where and how an element's sprite is drawn: what every sprite kind shares (the CPU image
//! here, the GL texture of ElementSprites.h, the instance records of the any-renderer API).
struct SpriteShape {
    float t = 0;                 //!< position on the flare vector
    float halfW = 0, halfH = 0;  //!< quad half size, frame pixels
    BlendMode blend = BlendMode::Add;
    bool edgeStreak = false;  //!< placed by edgeStreakPlacement instead of on the flare vector
    float reach = 0;          //!< edge streak: its reach (ElementParams::reach)
};

struct SpriteImage : SpriteShape {
    Image image;  //!< RGBA premultiplied, top row first, with a clear border
};

//! The sprites of `preset` for frames `height` pixels tall (element sizes are fractions of the
//! height); elements under half a pixel or without intensity get none.
std::vector<SpriteImage> renderSpriteImages(const Preset& preset, int height);

}  // namespace flarekit
