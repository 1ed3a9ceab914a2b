// SPDX-License-Identifier: Apache-2.0
// The instance data of the any-renderer API (fk_flare_set_instances): light_flare.vert's
// placement and weighting of one preset element over every light, on the CPU, one record per
// drawn quad. It reads as that shader does, step for step, so a renderer drawing the records
// with flare_instance.vert draws what fk_engine_draw draws.
#pragma once

#include <span>
#include <vector>

#include "flare/SpriteImages.h"
#include "flarekit/flarekit.h"

namespace flarekit::engine {

//! What an element's quad needs of its sprite (SpriteImage without the image), and where the
//! renderer finds the image.
struct InstanceSprite : SpriteShape {
    int slot = 0;     //!< its texture slot in the set
    int element = 0;  //!< its index among the preset's sprites
};

//! Appends the drawn instances of preset `presetId`'s `sprites` over `lights` (coverage[i]
//! weighs light i), element by element, in light order within each.
void appendFlareInstances(const fk_frame& frame, const fk_light* lights, const float* coverage,
                          int count, int presetId, std::span<const InstanceSprite> sprites,
                          float edgeFadeWidth, std::vector<fk_flare_instance>& out);

}  // namespace flarekit::engine
