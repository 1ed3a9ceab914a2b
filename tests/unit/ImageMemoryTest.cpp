// SPDX-License-Identifier: Apache-2.0
// Pixel buffers are recycled between images of one size: a new image is still transparent
// black however the buffer was used before, and an uncleared one has its size and takes writes.
#include <gtest/gtest.h>

#include <algorithm>

#include "flarekit/Image.h"

namespace flarekit {
namespace {

bool allZero(const Image& image) {
    return std::all_of(image.data(), image.data() + image.pixelCount() * 4,
                       [](float v) { return v == 0.f; });
}

TEST(ImageMemory, ANewImageIsBlackAfterItsBufferHeldAnotherImage) {
    for (int side : {64, 512, 1024}) {  // a heap buffer, and mapped ones (1 MiB and up)
        for (int round = 0; round < 3; ++round) {
            {
                Image used(side, side);
                used.fill({7.f, 8.f, 9.f, 1.f});
            }
            {
                Image uncleared(side, side, Image::Uncleared{});
                ASSERT_EQ(uncleared.width(), side);
                ASSERT_EQ(uncleared.pixelCount(), std::size_t(side) * std::size_t(side));
                uncleared.fill({1.f, 2.f, 3.f, 4.f});
                EXPECT_EQ(uncleared.at(side - 1, side - 1).a, 4.f);
            }
            EXPECT_TRUE(allZero(Image(side, side))) << side << " round " << round;
        }
    }
}

TEST(ImageMemory, AnEmptyUnclearedImageHasNoPixels) {
    const Image empty(0, 5, Image::Uncleared{});
    EXPECT_TRUE(empty.empty());
    EXPECT_EQ(empty.pixelCount(), 0u);
}

}  // namespace
}  // namespace flarekit
