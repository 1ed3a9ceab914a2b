// SPDX-License-Identifier: Apache-2.0
// 8/16-bit frames: a light needs a core at the file's white in every channel, as it shows
// (colour x alpha for straight colour).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "LightImages.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"

using namespace flarekit;
using namespace flarekit::test;

// 8-bit: a light needs a core at white in all three channels. A soft bright dome that peaks at
// code 245 without clipping (water under a soft sky, snow) and a warm highlight clipped in red
// only are not lights; a clipped sun is, and so is one in a file whose white is code 250
// (a plateau of pixels there: the file's own white point).
TEST(LightFinder, APhotosLightNeedsACoreAtWhiteInEveryChannel) {
    Image dome = background(640, 360, 0.02f);
    const float peak = srgbToLinear(245.f / 255.f);
    for (int y = 0; y < 360; ++y)
        for (int x = 0; x < 640; ++x) {
            const float d = std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 100.f);
            const float v = 0.02f + (peak - 0.02f) * std::exp(-(d / 20.f) * (d / 20.f));
            dome.at(x, y) = {v, v, v, 1.f};
        }
    const LightSearch soft = findLights(dome);
    ASSERT_TRUE(soft.displayReferred);
    EXPECT_TRUE(soft.lights.empty()) << soft.lights.front().verdict;
    EXPECT_NE(soft.whyNone.find("not clipped"), std::string::npos) << soft.whyNone;

    Image warm = background(640, 360, 0.02f);
    colouredBlob(warm, 400.f, 100.f, 24.f, {1.f, 0.93f, 0.75f, 1.f}, 0.f);
    const LightSearch redOnly = findLights(warm);
    EXPECT_TRUE(redOnly.lights.empty()) << redOnly.lights.front().verdict;

    for (const float code : {255.f, 250.f}) {
        Image sun = background(640, 360, 0.02f);
        const float white = srgbToLinear(code / 255.f);
        colouredBlob(sun, 400.f, 100.f, 24.f, {white, white, white, 1.f}, 0.6f * white);
        const LightSearch found = findLights(sun);
        ASSERT_EQ(found.lights.size(), 1u) << code << ": " << found.whyNone;
        EXPECT_TRUE(found.lights[0].clipped);
        EXPECT_NEAR(double(found.lights[0].whitePixels), 3.14159 * 24 * 24, 60.0);
    }
}

// A few clipped pixels in a soft bright region (a glint on water) are not a light's core.
TEST(LightFinder, AClippedSpeckInASoftRegionIsNotALight) {
    Image img = background(640, 360, 0.02f);
    colouredBlob(img, 400.f, 100.f, 24.f, {0.92f, 0.92f, 0.92f, 1.f}, 0.5f);
    img.at(400, 100) = img.at(401, 100) = {1.f, 1.f, 1.f, 1.f};
    const LightSearch search = findLights(img);
    EXPECT_TRUE(search.lights.empty()) << search.lights.front().verdict;
}

// A sunlit white object: a broad plateau just under white with clipped spots in a quarter of
// it is not a light's core (a light's region is mostly at white).
TEST(LightFinder, APlateauUnderWhiteWithClippedSpotsIsNotALight) {
    Image img = background(640, 360, 0.02f);
    colouredBlob(img, 400.f, 100.f, 30.f, {0.95f, 0.95f, 0.95f, 1.f}, 0.5f);
    for (int y = 70; y < 130; ++y)
        for (int x = 370; x < 430; ++x)
            if (x % 2 == 0 && y % 2 == 0 &&
                std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 100.f) < 30.f)
                img.at(x, y) = {1.f, 1.f, 1.f, 1.f};
    const LightSearch search = findLights(img);
    EXPECT_TRUE(search.lights.empty()) << search.lights.front().verdict;
    EXPECT_NE(search.whyNone.find("mostly under white"), std::string::npos) << search.whyNone;
}

// An 8/16-bit file holds straight colour: a pixel shows colour x alpha. A clipped sun (white,
// opaque) is a light; the same white drawn see-through (a logo or a graphic's glassy part at
// alpha 0.35) shows a grey of 0.35 and is none. A float frame holds premultiplied colour, so a
// rendered glow at alpha 0 (emission) is still a light.
TEST(LightFinder, SeeThroughWhiteIsNoLightButEmissionIs) {
    const auto withAlpha = [](Image img, float alpha, bool discOnly) {
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                if (!discOnly ||
                    std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 100.f) < 40.f)
                    img.at(x, y).a = alpha;
        return img;
    };
    Image photo = background(640, 360, 0.02f);
    blob(photo, 400.f, 100.f, 24.f, 1.f, 0.6f);
    ASSERT_EQ(findLights(photo).lights.size(), 1u) << findLights(photo).whyNone;
    for (const bool discOnly : {false, true}) {
        const LightSearch glassy = findLights(withAlpha(photo, 0.35f, discOnly));
        EXPECT_TRUE(glassy.lights.empty()) << discOnly;
        EXPECT_EQ(measureLightAt(withAlpha(photo, 0.35f, discOnly), {400.f, 100.f}).flux <
                      0.5 * measureLightAt(photo, {400.f, 100.f}).flux,
                  true);
    }
    Image render = background(640, 360, 0.1f);
    blob(render, 250.5f, 80.25f, 3.f, 5000.f);
    const LightSearch emission = findLights(withAlpha(render, 0.f, false));
    ASSERT_EQ(emission.lights.size(), 1u) << emission.whyNone;
    EXPECT_EQ(emission.lights[0].flux, findLights(render).lights[0].flux);
}
