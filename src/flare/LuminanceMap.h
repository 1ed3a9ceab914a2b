// SPDX-License-Identifier: Apache-2.0
// The light finder's luminance pass: each pixel's linear luminance once, the frame's brightest
// channel and peak, and (8/16-bit frames) the level of the file's white, as each pixel shows.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "flarekit/Image.h"

namespace flarekit::lightfinder {

//! A display-referred pixel is clipped to white when its luminance reaches this (sRGB grey 243
//! is 0.90 linear): a light burns out all three channels, with JPEG noise and a warm cast
//! just under 255, while a saturated orange leaf or a pink sky clips one channel only.
constexpr float kClipLevel = 0.9f;
//! What an 8/16-bit light needs at its core: every channel at the file's white, the top code,
//! or the file's own white point when it stops short of it (limited-range video whites at code
//! 235; a JPEG of a clipped sun often peaks at 250-254), within kWhiteToleranceCodes of it for
//! JPEG's ringing. A bright but unclipped region (water under a soft sky, snow, a lit wall, a
//! cloud) or a warm highlight clipped in one channel has no such core.
constexpr float kLowestWhiteCode = 235.f, kWhiteToleranceCodes = 3.f;

struct LuminanceMap {
    int w = 0, h = 0;
    // Pixel memory (see Image.h): every element is written by luminanceMap, none cleared first.
    std::vector<float, PixelAllocator<float>> lum;
    float brightestChannel = 0.f;  //!< of the whole frame: decides display- or scene-referred
    std::size_t peakIndex = 0;     //!< the first pixel (raster order) of the largest luminance
    //! Display-referred frames: the level every channel of a pixel at the file's white reaches
    //! (kLowestWhiteCode); infinite where the file has no white. Asked of a region's pixels
    //! only, so no pass marks the whole frame.
    float whiteLevel = std::numeric_limits<float>::infinity();
    const Image* image = nullptr;  //!< the frame measured (outlives the map)
    //! A display-referred frame with transparent pixels: its colour is straight (PNG, TIFF), so
    //! a pixel shows colour x alpha; white at alpha 0.3 is no light (a logo's see-through
    //! part). Float frames hold premultiplied colour (EXR) and are measured as stored, so
    //! emission at alpha 0 (a rendered glow) stays light.
    bool straightAlpha = false;
    float at(int x, int y) const { return lum[std::size_t(y) * std::size_t(w) + std::size_t(x)]; }
    bool clipped(std::size_t i) const { return lum[i] >= kClipLevel; }
    bool whiteCore(std::size_t i) const {
        const Rgba& p = reinterpret_cast<const Rgba*>(image->data())[i];  // rows are contiguous
        return shownNeutral(p, straightAlpha) >= whiteLevel;
    }
    //! The pixel's largest level in all three channels as it shows: min(R, G, B), times its
    //! alpha when the colour is straight.
    static float shownNeutral(const Rgba& p, bool straight) {
        const float neutral = std::min({p.r, p.g, p.b});
        return straight ? neutral * std::clamp(p.a, 0.f, 1.f) : neutral;
    }
};

//! The luminance pass over `image` (twice for a display-referred frame with see-through
//! pixels, the second as it shows), and its white level where it is display-referred.
LuminanceMap luminanceMap(const Image& image);

}  // namespace flarekit::lightfinder
