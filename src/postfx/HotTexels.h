// SPDX-License-Identifier: Apache-2.0
// Where a thresholded tap can find light: the ghosts and the halo subtract a threshold from
// every bloom sample and keep what is above it, so on a frame with a few small lights (a night
// street, the flare-data generator's suns) nearly all of their taps read exactly nothing. The
// CPU draws of those passes skip a ghost (or the halo) at a pixel when none of its taps can
// reach a texel above the threshold; what they write is the pixel kernel's result bit for bit
// (tested), and the GLSL twins run the kernels unchanged.
#pragma once

#include <algorithm>
#include <limits>

#include "postfx/Kernel.h"

namespace flarekit::postfx {

//! The texel columns and rows of a texture that hold light above a threshold, as the bounds a
//! tap's position (in texel coordinates: s * size - 0.5, as bilinear() computes them) must
//! come within to read any of it.
class HotTexels {
  public:
    //! Scans `t` for texels whose red, green or blue is above `threshold`, or negative or NaN
    //! (which a tap could also turn into light). A texel counts as cold only when every channel
    //! lies in [0, threshold x (1 - 1e-5)]: bilinear() mixes four such texels with two rounded
    //! lerps, whose error (a few float ulps, 1e-7 relative) cannot reach the threshold, so
    //! max0(tap - threshold) is exactly 0 for a tap reading only cold texels. A threshold of 0
    //! makes only exact zeros cold (a lerp of zeros is 0).
    HotTexels(const Tex& t, float threshold) {
        const float cut = threshold * (1.f - 1e-5f);
        const auto cold = [cut](float v) { return v >= 0.f && v <= cut; };
        int x0 = t.width, y0 = t.height, x1 = -1, y1 = -1;
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x < t.width; ++x) {
                const F4 v = t.texel(x, y);
                if (cold(v[0]) && cold(v[1]) && cold(v[2])) continue;
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        m_empty = x1 < 0;
        // A tap at texel coordinate sx reads columns floor(sx) and floor(sx) + 1, clamped to
        // the edge: it can reach column x0 from above x0 - 1 and x1 from below x1 + 1, and a
        // hot texel on the edge from anywhere beyond it.
        constexpr float inf = std::numeric_limits<float>::infinity();
        m_lo = {x0 == 0 ? -inf : float(x0) - 1.f, y0 == 0 ? -inf : float(y0) - 1.f};
        m_hi = {x1 == t.width - 1 ? inf : float(x1) + 1.f,
                y1 == t.height - 1 ? inf : float(y1) + 1.f};
    }

    //! True when no tap inside the box [lo, hi] (texel coordinates) reads a hot texel. The
    //! margin of 0.01 texel covers the rounding of the caller's bound against the kernel's own
    //! arithmetic of each tap (float positions of at most a few thousand texels: 1e-3 at most).
    bool misses(Vec2 lo, Vec2 hi) const {
        constexpr float margin = 0.01f;
        return m_empty || hi.x + margin < m_lo.x || lo.x - margin > m_hi.x ||
               hi.y + margin < m_lo.y || lo.y - margin > m_hi.y;
    }

  private:
    bool m_empty = true;
    Vec2 m_lo, m_hi;
};

//! Normalised texture coordinate s (as a kernel passes to bilinear()) in texel coordinates.
inline Vec2 texelCoord(const Tex& t, Vec2 s) {
    return {s.x * float(t.width) - 0.5f, s.y * float(t.height) - 0.5f};
}

}  // namespace flarekit::postfx
