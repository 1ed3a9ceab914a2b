// SPDX-License-Identifier: Apache-2.0
// --light auto: which regions are lights, where they are, how much flux they carry and which of
// them are one light. Fluxes are summed here from the images the tests draw, not taken from
// flarekit. The 8-bit white core: LightFinderWhiteCoreTest.cpp; HDR suns: LightFinderHdrTest.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "LightImages.h"
#include "flarekit/Flare.h"

using namespace flarekit;
using namespace flarekit::test;

TEST(LightFinder, AnHdrSunIsFoundAtItsCentroidWithItsFlux) {
    Image img = background(400, 300, 0.1f);
    blob(img, 250.5f, 80.25f, 3.f, 5000.f);
    const LightSearch search = findLights(img);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    const LightCandidate& sun = search.lights[0];
    EXPECT_FALSE(search.displayReferred);
    EXPECT_NEAR(sun.position.x, 250.5f, 0.1f);
    EXPECT_NEAR(sun.position.y, 80.25f, 0.3f);  // a 3-pixel disc is centred to a pixel grid
    const double flux = discFlux(img, 250.5f, 80.25f, 3.f);
    EXPECT_NEAR(sun.flux / flux, 1.0, 1e-6);
    // The energy model: flux in frame heights squared over the reference flux, linear.
    EXPECT_NEAR(sun.flareScale, flux / (300.0 * 300.0) / kReferenceFlux, 1e-6);
    EXPECT_EQ(sun.verdict, "light");
}

TEST(LightFinder, FlareScaleIsLinearInFluxAndIndependentOfResolution) {
    float scale[2];
    for (int k : {1, 2}) {
        Image img = background(320 * k, 180 * k, 0.05f);
        blob(img, 200.f * float(k), 60.f * float(k), 4.f * float(k), 3000.f);
        const LightSearch search = findLights(img);
        ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
        scale[k - 1] = search.lights[0].flareScale;
    }
    EXPECT_NEAR(scale[1] / scale[0], 1.f, 0.03f);  // same light, twice the pixels
    Image brighter = background(320, 180, 0.05f);
    blob(brighter, 200.f, 60.f, 4.f, 6000.f);
    EXPECT_NEAR(findLights(brighter).lights.at(0).flareScale / scale[0], 2.f, 1e-3f);
}

TEST(LightFinder, AClippedLightWithGlareInAPhotoCountsClippedPixelsAtTheGain) {
    Image img = background(640, 360, 0.02f);
    blob(img, 400.f, 100.f, 30.f, 1.f, 0.6f);  // clipped disc, soft glare around it
    LightSearchOptions options;
    const LightSearch search = findLights(img, options);
    ASSERT_TRUE(search.displayReferred);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    const LightCandidate& light = search.lights[0];
    EXPECT_TRUE(light.clipped);
    EXPECT_NEAR(light.position.x, 400.f, 0.5f);
    // Clipped pixels (luminance >= 0.9) count clippedGain each; the light's region is the pixels
    // within 90% of its peak, all of them clipped here.
    EXPECT_NEAR(light.flux, double(light.pixels) * options.clippedGain, 1e-6);
    EXPECT_GE(double(light.pixels), discFlux(img, 400.f, 100.f, 30.f));
}

TEST(LightFinder, NoLightInADimOrBlackImageSaysWhy) {
    const LightSearch dim = findLights(background(64, 64, 0.2f));
    EXPECT_TRUE(dim.lights.empty());
    EXPECT_NE(dim.whyNone.find("below --light-threshold"), std::string::npos) << dim.whyNone;
    EXPECT_TRUE(findLights(Image(64, 64)).lights.empty());
}

TEST(LightFinder, WhiteObjectsWithHardEdgesAreNotLights) {
    // A white wall: a clipped rectangle with a hard edge against a grey street.
    Image wall = background(640, 360, 0.25f);
    for (int y = 100; y < 220; ++y)
        for (int x = 200; x < 330; ++x) wall.at(x, y) = {1.f, 1.f, 1.f, 1.f};
    const LightSearch a = findLights(wall);
    EXPECT_TRUE(a.lights.empty()) << a.candidates.at(0).verdict;
    EXPECT_NE(a.whyNone.find("no convincing light"), std::string::npos) << a.whyNone;
    // A 4-pixel glint on a boat's bow.
    Image glint = background(1280, 720, 0.1f);
    for (int y = 400; y < 402; ++y)
        for (int x = 600; x < 602; ++x) glint.at(x, y) = {1.f, 1.f, 1.f, 1.f};
    const LightSearch b = findLights(glint);
    EXPECT_TRUE(b.lights.empty());
    EXPECT_NE(b.whyNone.find("too small"), std::string::npos) << b.whyNone;
    // An overcast sky: bright, flat, nothing stands out.
    Image sky = background(640, 360, 0.6f);
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 640; ++x) sky.at(x, y) = {0.95f, 0.95f, 0.95f, 1.f};
    EXPECT_TRUE(findLights(sky).lights.empty());
}

TEST(LightFinder, HdrPatchesFarBelowALightAreNot) {
    // A bright window (40 x the median) is a region of sky, not a light.
    Image img = background(640, 360, 0.2f);
    blob(img, 300.f, 100.f, 40.f, 8.f);
    const LightSearch search = findLights(img);
    EXPECT_TRUE(search.lights.empty());
    EXPECT_NE(search.whyNone.find("median"), std::string::npos) << search.whyNone;
}

TEST(LightFinder, MaxLightsFlaresEachLampByItsOwnFluxMostFirst) {
    Image img = background(640, 360, 0.01f);
    blob(img, 100.f, 200.f, 2.f, 2000.f);
    blob(img, 300.f, 210.f, 3.f, 2000.f);
    blob(img, 500.f, 190.f, 1.5f, 2000.f);
    LightSearchOptions options;
    options.maxLights = 8;
    const LightSearch all = findLights(img, options);
    ASSERT_EQ(all.lights.size(), 3u) << all.whyNone;
    EXPECT_NEAR(all.lights[0].position.x, 300.f, 0.5f);
    EXPECT_NEAR(all.lights[1].position.x, 100.f, 0.5f);
    EXPECT_NEAR(all.lights[2].position.x, 500.f, 0.5f);
    for (const LightCandidate& lamp : all.lights) {
        const double flux = discFlux(img, lamp.position.x, lamp.position.y, 4.f);
        EXPECT_NEAR(lamp.flux / flux, 1.0, 0.02);
    }
    options.maxLights = 1;
    const LightSearch one = findLights(img, options);
    ASSERT_EQ(one.lights.size(), 1u);
    EXPECT_NEAR(one.lights[0].position.x, 300.f, 0.5f);
}

TEST(LightFinder, TheBrokenFringeOfASunIsItsGlareNotASecondLight) {
    Image img = background(640, 360, 0.05f);
    blob(img, 320.f, 100.f, 2.f, 30000.f);
    blob(img, 350.f, 110.f, 6.f, 200.f);  // a bright gap in branches next to the sun
    LightSearchOptions options;
    options.maxLights = 4;
    const LightSearch search = findLights(img, options);
    ASSERT_EQ(search.lights.size(), 1u);
    EXPECT_NEAR(search.lights[0].position.x, 320.f, 0.5f);
    bool sawGlare = false;
    for (const LightCandidate& c : search.candidates)
        sawGlare |= c.verdict.find("glare of the light at 320,100") != std::string::npos;
    EXPECT_TRUE(sawGlare);
}

TEST(LightFinder, FlareLightsDrawsOneFlarePerLight) {
    Image img = background(320, 180, 0.01f);
    blob(img, 80.f, 60.f, 2.f, 3000.f);
    blob(img, 240.f, 60.f, 2.f, 3000.f);
    LightSearchOptions options;
    options.maxLights = 2;
    const LightSearch search = findLights(img, options);
    ASSERT_EQ(search.lights.size(), 2u);
    Preset preset;
    ElementParams glow = defaultElement(ElementType::Glow);
    glow.size = 0.1f;
    preset.elements = {glow};
    const FlareStats stats = flareLights(img, preset, search);
    EXPECT_EQ(stats.elementsDrawn, 2u);
    // Both lights got a glow of the same strength: equal light 10 px out on either.
    EXPECT_NEAR(img.at(90, 60).r, img.at(250, 60).r, 1e-4f);
    EXPECT_GT(img.at(90, 60).r, 0.01f + 1e-3f);
}

// The frame is display-referred only when no channel passes white (a saturated HDR red of 3
// has a luminance of 0.64 but is no 8-bit pixel), the same test postfx's frameWhite makes; and
// the search reports where its peak is.
TEST(LightFinder, DisplayReferredIsJudgedOnTheBrightestChannelAndThePeakIsPlaced) {
    Image img = background(64, 48, 0.1f);
    img.at(20, 10) = {3.f, 0.f, 0.f, 1.f};
    const LightSearch hdr = findLights(img);
    EXPECT_FALSE(hdr.displayReferred);
    EXPECT_FLOAT_EQ(hdr.peakAt.x, 20.5f);
    EXPECT_FLOAT_EQ(hdr.peakAt.y, 10.5f);
    img.at(20, 10) = {1.f, 0.f, 0.f, 1.f};
    EXPECT_TRUE(findLights(img).displayReferred);
}

// One flare per physical light: a strip light found as bright spots 6 px apart (each its own
// peak) and a window found twice 16 px apart are one light each, with the summed flux at the
// flux-weighted centre; two lamps 60 px apart stay two.
TEST(LightFinder, SpotsOfOneStripOrWindowAreOneLightLampsApartAreTwo) {
    const Image img = stripWindowAndLamps();
    const auto& spots = kStripSpots;
    LightSearchOptions options;
    options.maxLights = 16;
    const LightSearch search = findLights(img, options);
    ASSERT_EQ(search.lights.size(), 4u) << search.whyNone;
    const LightCandidate* strip = nullptr;
    const LightCandidate* window = nullptr;
    int lamps = 0;
    for (const LightCandidate& l : search.lights) {
        if (std::fabs(l.position.y - 100.f) < 2.f) strip = &l;
        if (std::fabs(l.position.y - 250.f) < 2.f) window = &l;
        lamps += std::fabs(l.position.y - 80.f) < 2.f;
    }
    ASSERT_TRUE(strip && window);
    EXPECT_EQ(lamps, 2);
    double stripFlux = 0, weighted = 0;
    for (int i = 0; i < 4; ++i) {
        const double f = discFlux(img, spots[i], 100.f, 2.f);
        stripFlux += f;
        weighted += f * spots[i];
    }
    EXPECT_NEAR(strip->flux / stripFlux, 1.0, 0.02);
    EXPECT_NEAR(strip->position.x, weighted / stripFlux, 0.5);
    EXPECT_EQ(strip->verdict, "light (4 regions of one light)");
    const double windowFlux = discFlux(img, 420.f, 250.f, 5.5f) + discFlux(img, 436.f, 250.f, 5.5f);
    EXPECT_NEAR(window->flux / windowFlux, 1.0, 0.02);
    EXPECT_NEAR(window->flareScale, flareScaleForFlux(window->flux, 360), 1e-6);
    int parts = 0;
    for (const LightCandidate& c : search.candidates)
        parts += c.verdict.rfind("part of the light at", 0) == 0;
    EXPECT_EQ(parts, 4);  // three spots of the strip, one pane of the window
}

// With no light convincing, the warning names the candidate that came closest: a small HDR sun
// that is only too faint, not the wide glow around it that carries more flux but fails first.
TEST(LightFinder, TheWarningNamesTheClosestCandidateNotTheGlowWithMostFlux) {
    Image img = background(900, 512, 0.3f);
    blob(img, 600.f, 200.f, 60.f, 3.f);  // the aureole: 10x the median, far from a light
    blob(img, 614.5f, 246.5f, 0.8f, 2000.f);
    const LightSearch search = findLights(img);
    ASSERT_TRUE(search.lights.empty());
    EXPECT_NE(search.whyNone.find("the closest candidate, at 614,246 (peak 2000), is too faint"),
              std::string::npos)
        << search.whyNone;
}
