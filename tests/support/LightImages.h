// SPDX-License-Identifier: Apache-2.0
// Frames for the light finder's tests: discs of a value or a colour with a lens's veiling glare
// around them, on a flat background, and the flux a disc of a frame holds.
#pragma once

#include <cmath>

#include "flarekit/Image.h"

namespace flarekit::test {

//! A disc of `value`, plus (glare > 0) a glow around it falling as glare / (1 + 4 u^2), u the
//! distance past the rim in radii, the way a lens's veiling glare spreads a clipped light.
inline void blob(Image& img, float cx, float cy, float radius, float value, float glare = 0.f) {
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const float d = std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy);
            Rgba& p = img.at(x, y);
            const float u = d / radius - 1.f;
            const float v = d < radius ? value : p.r + glare / (1.f + 4.f * u * u);
            p = {v, v, v, 1.f};
        }
    }
}

inline Image background(int w, int h, float v) {
    Image img(w, h);
    img.fill({v, v, v, 1.f});
    return img;
}

inline double discFlux(const Image& img, float cx, float cy, float radius) {
    double sum = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            if (std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy) < radius)
                sum += img.at(x, y).r;
    return sum;
}

//! A disc of colour `core` (flat: clipped, or not) with a soft glare of `glare` around it.
inline void colouredBlob(Image& img, float cx, float cy, float radius, Rgba core, float glare) {
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float d = std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy);
            const float u = d / radius - 1.f;
            Rgba& p = img.at(x, y);
            if (d < radius) {
                p = core;
            } else {
                const float g = glare / (1.f + 4.f * u * u);
                p = {p.r + g, p.g + g, p.b + g, 1.f};
            }
        }
}

}  // namespace flarekit::test
