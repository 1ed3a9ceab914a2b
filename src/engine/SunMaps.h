// SPDX-License-Identifier: Apache-2.0
// Texture masking's sun maps for many lights (Maughan, "Texture Masking for Faster Lens
// Flare", Game Programming Gems 2, 2001): an atlas of one tile per light, each drawn by the
// application's occluder callback from a camera at the eye that sees exactly that light's
// cone. sunmap_coverage.comp then reduces every tile at once (EngineTextureMask.cpp).
#pragma once

#include <epoxy/gl.h>

#include "flarekit/Result.h"
#include "flarekit/flarekit.h"
#include "gl/GlObjects.h"

namespace flarekit::engine {

//! The atlas's tiles for `maxLights` lights: texels a side, and tiles a row (64 texels up to
//! 4,096 lights, smaller beyond, the atlas within 4096 x 4096).
struct TileLayout {
    int tileSize = 0, tilesPerRow = 0;
};
TileLayout tileLayout(int maxLights);

//! Light `l`'s sun-map camera for frame `f`: at the eye, looking along the light, its field of
//! view the light's cone, in the clip space of the frame's depth convention, column-major.
//! False (nothing to draw) when the camera is inside a sphere light.
bool sunMapCamera(const fk_frame& f, const fk_light& l, float viewProjection[16]);

class SunMapAtlas {
  public:
    //! Tiles for `maxLights` lights (a current GL context is needed).
    static Result<SunMapAtlas> create(int maxLights);
    //! Clears the atlas white and calls `occluders` once per light with a tile (tileOf[i] >=
    //! 0), that tile bound and set as the viewport (the caller restores the GL state). A camera
    //! inside a sphere light gets no call: the reduction counts it fully seen.
    void draw(int view, const fk_frame& f, const fk_light* lights, const int* tileOf, int count,
              fk_occluder_callback occluders, void* user) const;
    GLuint texture() const { return m_atlas.get(); }
    int tileSize() const { return m_tileSize; }
    int tilesPerRow() const { return m_tilesPerRow; }

  private:
    gl::Texture m_atlas;  //!< RGBA8, one tile per light
    gl::Framebuffer m_target;
    int m_tileSize = 0, m_tilesPerRow = 0;
};

}  // namespace flarekit::engine
