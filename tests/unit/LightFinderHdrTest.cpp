// SPDX-License-Identifier: Apache-2.0
// HDR frames: a sun clipped at capture (a plateau), a bright sky that is none, and a hazy
// sun whose aureole carries its light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "LightImages.h"
#include "flarekit/Flare.h"

using namespace flarekit;
using namespace flarekit::test;

// A sun clipped at capture: its disc a plateau of one value (here 60 over a sky of 0.3, 200x
// the median, under a light's 1000x) with a glow around it. The plateau is the evidence of a
// clip, so it is a light, and its pixels count at clippedGain x the plateau, as a clipped 8-bit
// light's count at clippedGain x white; the glow is its aureole.
TEST(LightFinder, ASunClippedAtCaptureIsALightWithItsPlateauAtTheGain) {
    Image img = background(640, 360, 0.3f);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float d = std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 120.f);
            Rgba& p = img.at(x, y);
            const float v = d < 5.f ? 60.f : 0.3f + 30.f / (1.f + 0.05f * d * d);
            p = {v, v, v, 1.f};
        }
    const LightSearch search = findLights(img);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    const LightCandidate& sun = search.lights[0];
    EXPECT_NEAR(sun.position.x, 400.f, 1.f);
    EXPECT_GE(sun.flatTopPixels, 60u);  // the disc of radius 5: 78 pixels at 60
    const double plateau = double(sun.flatTopPixels) * 60.0;
    EXPECT_GT(sun.flux, 4.0 * plateau);  // the plateau at the gain, plus its glow
    EXPECT_GT(sun.aureoleFlux, 0.0);
    // The same sun unclipped (a peak held by one pixel) at this contrast is no light.
    img.at(399, 119) = {61.f, 61.f, 61.f, 1.f};
    for (int y = 115; y < 125; ++y)
        for (int x = 395; x < 405; ++x)
            if (img.at(x, y).r >= 60.f && !(x == 399 && y == 119))
                img.at(x, y) = {40.f + float(x - 395) + float(y - 115), 0.f, 0.f, 1.f};
    const LightSearch peaked = findLights(img);
    EXPECT_TRUE(peaked.lights.empty()) << peaked.lights.front().verdict;
}

// A daylight frame whose range was cut at 22 (median 0.5: the plateau 44x over it, under the
// 50x a plateau needs): the plateau at the frame's peak is the capture's own clip, so the sun
// is a light. The same plateau under a brighter pixel elsewhere (a glint of 2,000) is no longer
// the frame's clip and needs its 50x.
TEST(LightFinder, APlateauAtTheFramesPeakIsItsClipInABrightFrame) {
    Image img = background(640, 360, 0.5f);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float d = std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 120.f);
            const float v = d < 6.f ? 22.f : 0.5f + 12.f / (1.f + 0.05f * d * d);
            img.at(x, y) = {v, v, v, 1.f};
        }
    const LightSearch search = findLights(img);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    EXPECT_NEAR(search.lights[0].position.x, 400.f, 1.f);
    EXPECT_GE(search.lights[0].flatTopPixels, 100u);  // the disc of radius 6: 113 pixels
    img.at(100, 300) = {2000.f, 2000.f, 2000.f, 1.f};
    for (const LightCandidate& c : findLights(img).lights)
        EXPECT_GT(std::fabs(c.position.x - 400.f), 10.f) << c.verdict;
}

// A bright sky's smooth crest (a broad glow, no plateau) is not taken for a clip: no plateau
// pixels, and at 20x the median no light.
TEST(LightFinder, ABrightSkysCrestIsNoPlateau) {
    Image img = background(640, 360, 0.25f);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float dx = float(x) - 300.f, dy = float(y) - 100.f;
            const float v = 0.25f + 5.f * std::exp(-(dx * dx + dy * dy) / (2.f * 60.f * 60.f));
            img.at(x, y) = {v, v, v, 1.f};
        }
    const LightSearch search = findLights(img);
    EXPECT_TRUE(search.lights.empty());
    ASSERT_FALSE(search.candidates.empty());
    EXPECT_EQ(search.candidates.front().flatTopPixels, 0u);
}

// A sun's aureole carries its light: a one-pixel core of 5,000 over a sky of 0.2, in a glow
// g(d) = 40 / (1 + (d / 6)^2). The aureole's flux is the glow's excess over the sky summed
// outside the core, within 25% (rings, not pixels, and the glow's tail past the last ring);
// the sun's flux is its core and that aureole, several times the core alone.
TEST(LightFinder, TheAureoleCarriesAHazySunsLight) {
    Image img = background(640, 360, 0.2f);
    double glow = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float d = std::hypot(float(x) + 0.5f - 320.5f, float(y) + 0.5f - 180.5f);
            const float g = 40.f / (1.f + (d / 6.f) * (d / 6.f));
            if (d > 2.f && d < 0.25f * 360.f) glow += g;
            img.at(x, y) = {0.2f + g, 0.2f + g, 0.2f + g, 1.f};
        }
    img.at(320, 180) = {5000.f, 5000.f, 5000.f, 1.f};
    const LightSearch search = findLights(img);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    const LightCandidate& sun = search.lights[0];
    EXPECT_NEAR(sun.aureoleFlux / glow, 1.0, 0.25) << sun.aureoleFlux << " vs " << glow;
    EXPECT_GE(sun.aureoleRings, 10);
    EXPECT_GT(sun.flux, 3.0 * 5000.0);  // the core alone: 5,000
}

// A hazy sun: a dim core (peak 44 at about 80x the median) in a wide aureole that carries most
// of its light is a light; the same core without the aureole, at that contrast, is not.
TEST(LightFinder, AHazySunIsFoundByItsAureole) {
    const auto sky = [](bool haze) {
        Image img = background(640, 360, 0.5f);
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const float d = std::hypot(float(x) + 0.5f - 420.5f, float(y) + 0.5f - 100.5f);
                float v = 0.5f + (haze ? 12.f / (1.f + (d / 12.f) * (d / 12.f)) : 0.f);
                if (d < 2.f) v = std::max(v, 44.f - 10.f * d);  // a peak, not a clipped plateau
                img.at(x, y) = {v, v, v, 1.f};
            }
        return img;
    };
    const LightSearch hazy = findLights(sky(true));
    ASSERT_EQ(hazy.lights.size(), 1u) << hazy.whyNone;
    EXPECT_NEAR(hazy.lights[0].position.x, 420.5f, 1.f);
    EXPECT_GE(hazy.lights[0].aureoleRings, 10);
    EXPECT_LT(hazy.lights[0].peak, 1000.f * hazy.frameKey);  // under a clear sun's contrast
    const LightSearch bare = findLights(sky(false));
    EXPECT_TRUE(bare.lights.empty());
    const auto core = std::find_if(bare.candidates.begin(), bare.candidates.end(),
                                   [](const LightCandidate& c) { return c.peak == 44.f; });
    ASSERT_NE(core, bare.candidates.end());
    EXPECT_NE(core->verdict.find("the frame's median luminance (a light is 1000x)"),
              std::string::npos)
        << core->verdict;
}
