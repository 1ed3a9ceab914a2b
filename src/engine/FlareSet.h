// SPDX-License-Identifier: Apache-2.0
// The any-renderer API behind fk_flare_set: presets, their sprite images for one frame height
// and the instance records of a frame's lights. No GL: a Direct3D, Metal or Vulkan renderer
// uploads the sprites and draws the records with the exported shaders (FlareShaders.h).
#pragma once

#include <string>
#include <vector>

#include "engine/FlareInstances.h"
#include "flare/SpriteImages.h"
#include "flarekit/Flare.h"
#include "flarekit/Result.h"
#include "flarekit/flarekit.h"

namespace flarekit::engine {

class FlareSet {
  public:
    //! A preset by shipped name or path, or (json) from text in memory; its id.
    Result<int> loadPreset(const std::string& nameOrPath);
    Result<int> loadPresetJson(const char* json, std::size_t length);
    //! Renders every preset's sprites for `height`; the number of slots.
    Result<int> prepare(int height);
    const SpriteImage* sprite(int slot) const;
    //! Every drawn record of `count` lights, in draw order.
    Status instances(const fk_frame* frame, const fk_light* lights, const float* coverage,
                     int count, float edgeFade, std::vector<fk_flare_instance>& out) const;

    std::string lastError;

  private:
    struct Loaded {
        Preset preset;
        std::vector<InstanceSprite> sprites;  //!< for m_height
    };
    std::vector<Loaded> m_presets;
    std::vector<SpriteImage> m_slots;  //!< every preset's sprites, in order
    int m_height = 0;                  //!< 0: not prepared since the last load
};

}  // namespace flarekit::engine
