// SPDX-License-Identifier: Apache-2.0
// A preset's sprite images (SpriteImages.h) as GL textures for frames of one height. Shared by
// GpuSpriteFlare (one sun) and the engine API (every light, instanced).
#pragma once

#include <vector>

#include "flare/SpriteImages.h"
#include "flarekit/Flare.h"
#include "gl/GlObjects.h"

namespace flarekit {

struct ElementSprite : SpriteShape {
    gl::Texture texture;  //!< RGBA16F premultiplied, top row first, clamped to a clear border
};

//! The sprites of `preset` for frames `height` pixels tall (element sizes are fractions of the
//! height); elements under half a pixel or without intensity get none.
Result<std::vector<ElementSprite>> buildElementSprites(const Preset& preset, int height);

}  // namespace flarekit
