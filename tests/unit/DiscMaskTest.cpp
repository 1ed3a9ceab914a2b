// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/DiscMask.h"

using namespace flarekit;

namespace {

//! The disc pixel by pixel over the whole mask: the definition markDisc must reproduce.
std::vector<std::uint8_t> discByPixel(int w, int h, float cx, float cy, float r) {
    std::vector<std::uint8_t> mask(std::size_t(w) * std::size_t(h), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (inDisc(cx, cy, r, x, y)) mask[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
    return mask;
}

}  // namespace

// Random discs inside, across and outside the edges of odd-sized masks, radii from below a
// pixel to past the frame, centres on and off pixel centres and edges: the spans are exactly
// the pixels the test accepts one by one.
TEST(DiscMask, SpansAreExactlyThePixelsOfTheTest) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    const int w = 97, h = 61;
    for (int i = 0; i < 3000; ++i) {
        float cx = -30.f + 160.f * unit(rng), cy = -30.f + 120.f * unit(rng);
        if (i % 3 == 0) cx = std::round(cx) + 0.5f, cy = std::round(cy);  // on centres, edges
        const float r = i % 7 == 0 ? unit(rng) : std::exp(5.f * unit(rng));
        std::vector<std::uint8_t> mask(std::size_t(w) * std::size_t(h), 0);
        markDisc(mask.data(), w, h, cx, cy, r);
        ASSERT_EQ(mask, discByPixel(w, h, cx, cy, r)) << cx << "," << cy << " r " << r;
    }
    // Integer radii about a pixel centre: the boundary pixels sit exactly on the circle.
    for (int r = 1; r < 40; ++r) {
        std::vector<std::uint8_t> mask(std::size_t(w) * std::size_t(h), 0);
        markDisc(mask.data(), w, h, 48.5f, 30.5f, float(r));
        ASSERT_EQ(mask, discByPixel(w, h, 48.5f, 30.5f, float(r))) << r;
        EXPECT_EQ(mask[30 * std::size_t(w) + 48 + std::size_t(std::min(r, 48))], 1) << r;
    }
}

// Marking adds to what the mask holds: pixels set before stay set.
TEST(DiscMask, MarksWithoutClearing) {
    std::vector<std::uint8_t> mask(20 * 10, 0);
    mask[0] = 1;
    markDisc(mask.data(), 20, 10, 15.f, 5.f, 2.f);
    EXPECT_EQ(mask[0], 1);
    EXPECT_EQ(mask[5 * 20 + 15], 1);
    EXPECT_EQ(mask[5 * 20 + 10], 0);
}
