// SPDX-License-Identifier: Apache-2.0
#include "flare/LuminanceMap.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/LuminanceSample.h"
#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"

namespace flarekit::lightfinder {

namespace {

//! A file's own white point below the top code counts only where the file piles pixels up
//! there, as a clip does (a sun's clipped disc is hundreds of pixels at one level); a natural
//! highlight's brightest level is held by a handful of pixels.
constexpr std::size_t kWhitePlateauPixels = 16;

//! The level at which a display-referred frame's three channels are at its white: the top code,
//! or the brightest neutral level of the file if it stops between kLowestWhiteCode and the top
//! and holds a plateau there (the file's own white point), less kWhiteToleranceCodes. Infinite
//! when the file has no white. `brightestNeutral`: the frame's largest shownNeutral.
float whiteLevelOf(const Image& image, float brightestNeutral, bool straight) {
    constexpr float kNone = std::numeric_limits<float>::infinity();
    const float white = std::min(1.f, brightestNeutral);
    const float whiteCode = linearToSrgb(white) * 255.f;
    if (whiteCode < kLowestWhiteCode - 0.5f) return kNone;  // nothing in the file reaches a white
    if (whiteCode < 254.5f) {
        // Short of the top code: a white point only where pixels pile up at it.
        const float level = srgbToLinear((whiteCode - 0.5f) / 255.f);
        std::atomic<std::size_t> count{0};
        parallelFor(0, image.height(), 32, [&](int y0, int y1) {
            std::size_t n = 0;
            for (int y = y0; y < y1; ++y) {
                const Rgba* row = &image.at(0, y);
                for (int x = 0; x < image.width(); ++x)
                    n += LuminanceMap::shownNeutral(row[x], straight) >= level;
            }
            count += n;
        });
        if (count.load() < kWhitePlateauPixels) return kNone;  // a natural highlight
    }
    return srgbToLinear((std::round(whiteCode) - kWhiteToleranceCodes) / 255.f);
}

//! One pass of the luminance map: each pixel's luminance (times its alpha for straight
//! colour), the rows' peaks, brightest channels and brightest neutrals; the frame's lowest alpha.
void luminancePass(const Image& image, LuminanceMap& m, std::vector<float>& rowWhite,
                   float& lowestAlpha) {
    std::vector<float> rowBrightest(std::size_t(m.h), 0.f), rowAlpha(std::size_t(m.h), 1.f);
    std::vector<std::size_t> rowPeak(std::size_t(m.h), 0);
    const bool straight = m.straightAlpha;
    parallelFor(0, m.h, 32, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const Rgba* row = &image.at(0, y);
            const std::size_t first = std::size_t(y) * std::size_t(m.w);
            float brightest = 0.f, white = 0.f, alpha = 1.f;
            std::size_t peak = first;
            for (int x = 0; x < m.w; ++x) {
                const std::size_t i = first + std::size_t(x);
                float l = luminance(row[x].r, row[x].g, row[x].b);
                if (straight) l *= std::clamp(row[x].a, 0.f, 1.f);
                m.lum[i] = std::isfinite(l) ? std::max(l, 0.f) : 0.f;
                if (m.lum[i] > m.lum[peak]) peak = i;
                brightest = std::max({brightest, row[x].r, row[x].g, row[x].b});
                white = std::max(white, LuminanceMap::shownNeutral(row[x], straight));
                alpha = std::min(alpha, row[x].a);
            }
            rowBrightest[std::size_t(y)] = brightest;
            rowWhite[std::size_t(y)] = white;
            rowAlpha[std::size_t(y)] = alpha;
            rowPeak[std::size_t(y)] = peak;
        }
    });
    m.brightestChannel = *std::max_element(rowBrightest.begin(), rowBrightest.end());
    m.peakIndex = 0;
    for (const std::size_t peak : rowPeak)
        if (m.lum[peak] > m.lum[m.peakIndex]) m.peakIndex = peak;
    lowestAlpha = *std::min_element(rowAlpha.begin(), rowAlpha.end());
}

}  // namespace

LuminanceMap luminanceMap(const Image& image) {
    LuminanceMap m;
    m.w = image.width(), m.h = image.height(), m.image = &image;
    m.lum.resize(image.pixelCount());
    std::vector<float> rowWhite(std::size_t(m.h), 0.f);
    float lowestAlpha = 1.f;
    luminancePass(image, m, rowWhite, lowestAlpha);
    if (!isDisplayReferred(m.brightestChannel)) return m;
    if (lowestAlpha < 1.f) {
        // Straight colour with see-through pixels: measured again as it shows.
        m.straightAlpha = true;
        luminancePass(image, m, rowWhite, lowestAlpha);
    }
    m.whiteLevel =
        whiteLevelOf(image, *std::max_element(rowWhite.begin(), rowWhite.end()), m.straightAlpha);
    return m;
}

}  // namespace flarekit::lightfinder
