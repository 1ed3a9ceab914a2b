// SPDX-License-Identifier: Apache-2.0
// Test images made from a formula of the pixel and a seeded uniform source.
#pragma once

#include <random>

#include "flarekit/Image.h"

namespace flarekit::test {

//! A width x height image whose pixel (x, y) is pixel(x, y, unit), `unit()` drawing uniform
//! values in [0, 1) from a generator seeded with `seed`, pixels in raster order.
template <class Pixel>
Image imageOf(int width, int height, unsigned seed, Pixel pixel) {
    Image image(width, height);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.f, 1.f);
    const auto unit = [&] { return uniform(rng); };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = pixel(x, y, unit);
    return image;
}

}  // namespace flarekit::test
