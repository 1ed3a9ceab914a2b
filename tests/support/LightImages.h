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

//! One physical light found as several regions, and two that are not one: a strip light's
//! four spots 6 px apart along y = 100 (x = kStripSpots), a window's two panes 16 px apart at
//! (420, 250) and (436, 250), and two lamps 60 px apart at (560, 80) and (620, 80).
inline constexpr float kStripSpots[] = {200.f, 206.f, 212.f, 218.f};
inline Image stripWindowAndLamps() {
    Image img = background(640, 360, 0.01f);
    const float values[] = {3000.f, 2600.f, 2800.f, 2400.f};
    for (int i = 0; i < 4; ++i) blob(img, kStripSpots[i], 100.f, 1.5f, values[i]);
    blob(img, 420.f, 250.f, 5.f, 1500.f);
    blob(img, 436.f, 250.f, 5.f, 1200.f);
    blob(img, 560.f, 80.f, 2.f, 2000.f);
    blob(img, 620.f, 80.f, 2.f, 2000.f);
    return img;
}

}  // namespace flarekit::test
