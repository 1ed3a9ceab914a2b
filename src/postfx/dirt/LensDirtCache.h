// SPDX-License-Identifier: Apache-2.0
// The dirt texture of the last run, regenerated only when its size, seed or speck count
// changes: both chains keep one, so a video pays makeLensDirt once.
#pragma once

#include "flarekit/PostFx.h"

namespace flarekit::postfx {

class LensDirtCache {
  public:
    //! True when the texture was (re)generated for this size and params (the GL chain uploads it
    //! then).
    bool update(int width, int height, const DirtParams& params) {
        if (m_valid && m_key.seed == params.seed && m_key.spots == params.spots &&
            m_image.width() == width && m_image.height() == height) {
            return false;
        }
        m_image = makeLensDirt(width, height, params);
        m_key = params, m_valid = true;
        return true;
    }
    //! Forget the texture (the GL chain's target was reallocated).
    void invalidate() { m_valid = false; }
    const Image& image() const { return m_image; }

  private:
    Image m_image;
    DirtParams m_key;
    bool m_valid = false;
};

}  // namespace flarekit::postfx
