// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include "flarekit/Blend.h"

using namespace flarekit;

TEST(Composite, AddSumsColourAndKeepsDestinationAlpha) {
    float src[8] = {0.5f, 2.f, 0.f, 1.f, 10.f, 0.f, 0.25f, 0.3f};
    float dst[8] = {0.25f, 0.5f, 3.f, 0.7f, 40.f, 1.f, 0.f, 1.f};
    compositeSpan(BlendMode::Add, src, dst, 2);
    const float want[8] = {0.75f, 2.5f, 3.f, 0.7f, 50.f, 1.f, 0.25f, 1.f};
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(dst[i], want[i]) << i;
}

TEST(Composite, ScreenAndOverFollowTheirDefinitions) {
    float src[4] = {0.5f, 0.2f, 0.f, 0.5f};
    float dst[4] = {0.5f, 0.5f, 1.f, 1.f};
    compositeSpan(BlendMode::Screen, src, dst, 1);
    EXPECT_FLOAT_EQ(dst[0], 0.75f);  // 1 - 0.5*0.5
    EXPECT_FLOAT_EQ(dst[1], 0.6f);   // 1 - 0.8*0.5
    EXPECT_FLOAT_EQ(dst[2], 1.f);
    float over[4] = {0.5f, 0.5f, 1.f, 1.f};
    compositeSpan(BlendMode::Over, src, over, 1);  // src is premultiplied
    EXPECT_FLOAT_EQ(over[0], 0.5f + 0.25f);
    EXPECT_FLOAT_EQ(over[2], 0.5f);
    EXPECT_FLOAT_EQ(over[3], 1.f);
}

TEST(Composite, NamesRoundTrip) {
    for (auto m : {BlendMode::Add, BlendMode::Screen, BlendMode::Over})
        EXPECT_EQ(parseBlendMode(blendModeName(m)), m);
    EXPECT_FALSE(parseBlendMode("multiply"));
}
