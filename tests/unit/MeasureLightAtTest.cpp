// SPDX-License-Identifier: Apache-2.0
// --light X,Y: a hand-placed light measured as the finder measures the light it finds, inside
// the frame, across its edge and beyond it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "LightImages.h"
#include "flarekit/Flare.h"

using namespace flarekit;
using namespace flarekit::test;

// A hand-placed light is measured as the finder measures the light it finds: placed anywhere
// on or beside the sun (within 2% of the height), it has the found sun's flux and flare scale.
TEST(MeasureLightAt, APlacedLightHasTheFluxTheFinderMeasuresThere) {
    for (const bool clippedPhoto : {false, true}) {
        Image img = background(640, 360, clippedPhoto ? 0.02f : 0.1f);
        if (clippedPhoto)
            blob(img, 400.f, 100.f, 24.f, 1.f, 0.6f);
        else
            blob(img, 250.5f, 80.25f, 3.f, 5000.f);
        const LightSearch search = findLights(img);
        ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
        const LightCandidate& found = search.lights[0];
        for (const Point offset : {Point{0, 0}, Point{3, -2}, Point{-5, 4}}) {
            const Point at{found.position.x + offset.x, found.position.y + offset.y};
            const LightCandidate placed = measureLightAt(img, at);
            EXPECT_EQ(placed.flux, found.flux) << clippedPhoto << " " << offset.x;
            EXPECT_EQ(placed.flareScale, found.flareScale);
            EXPECT_EQ(placed.pixels, found.pixels);
        }
    }
}

// One flare per physical light, placed or found: a point on any spot of a strip light or on
// either pane of a window has the flux of the one light the finder makes of them; a lamp 60 px
// from another keeps its own.
TEST(MeasureLightAt, APlacedLightOnAPartOfOneLightHasThatWholeLightsFlux) {
    const Image img = stripWindowAndLamps();
    LightSearchOptions options;
    options.maxLights = 16;
    const LightSearch search = findLights(img, options);
    ASSERT_EQ(search.lights.size(), 4u) << search.whyNone;
    const auto foundNear = [&](float y) {
        for (const LightCandidate& l : search.lights)
            if (std::fabs(l.position.y - y) < 2.f) return l;
        ADD_FAILURE() << "no light at y " << y;
        return LightCandidate{};
    };
    const LightCandidate strip = foundNear(100.f), window = foundNear(250.f);
    for (const float x : kStripSpots) {
        const LightCandidate placed = measureLightAt(img, {x, 100.f});
        EXPECT_EQ(placed.flux, strip.flux) << x;
        EXPECT_EQ(placed.flareScale, strip.flareScale) << x;
        EXPECT_NE(placed.verdict.find("on the light at"), std::string::npos) << placed.verdict;
    }
    for (const float x : {420.f, 436.f})
        EXPECT_EQ(measureLightAt(img, {x, 250.f}).flux, window.flux) << x;
    // A lamp is its own light: the same flux as the finder's lamp there, not the pair's sum.
    double lampFlux = 0;
    for (const LightCandidate& l : search.lights)
        if (std::fabs(l.position.x - 560.f) < 2.f) lampFlux = l.flux;
    ASSERT_GT(lampFlux, 0);
    EXPECT_EQ(measureLightAt(img, {560.f, 80.f}).flux, lampFlux);
    // The part measured alone is less than the light: the test would see a placed light that
    // measured only its own spot.
    EXPECT_LT(discFlux(img, 200.f, 100.f, 2.f), 0.5 * strip.flux);
}

// In HDR data the finder counts a sun's aureole and a capture clip's plateau at the gain; a
// light placed on the same sun counts them too (before, a placed hazy or clipped sun had only
// its core: 59% and less of the found flux).
TEST(MeasureLightAt, APlacedHdrSunCountsItsAureoleAndItsClipAsTheFinderDoes) {
    const auto sunOn = [](float coreRadius, float core, float glow) {
        Image img = background(640, 360, 0.3f);
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const float d = std::hypot(float(x) + 0.5f - 400.f, float(y) + 0.5f - 120.f);
                const float v = d < coreRadius ? core : 0.3f + glow / (1.f + 0.05f * d * d);
                img.at(x, y) = {v, v, v, 1.f};
            }
        return img;
    };
    // A capture clip (a plateau of 60, 200x the median) and a one-pixel sun of 5,000 in a glow.
    for (const Image& img : {sunOn(5.f, 60.f, 30.f), sunOn(0.8f, 5000.f, 40.f)}) {
        const LightSearch search = findLights(img);
        ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
        const LightCandidate& found = search.lights[0];
        ASSERT_GT(found.aureoleFlux, 0.0);
        const LightCandidate placed =
            measureLightAt(img, {found.position.x + 2.f, found.position.y});
        EXPECT_EQ(placed.flux, found.flux);
        EXPECT_EQ(placed.flareScale, found.flareScale);
        EXPECT_EQ(placed.flatTopPixels, found.flatTopPixels);
    }
}

TEST(MeasureLightAt, NothingThereIsNoFluxASkyLittleAndFarOutsideTheFrameNone) {
    Image img = background(320, 180, 0.f);
    blob(img, 200.f, 60.f, 4.f, 3000.f);
    // Far from the light (more than 2% of the height): black, so no flux and no flare.
    const LightCandidate dark = measureLightAt(img, {40.f, 150.f});
    EXPECT_EQ(dark.flux, 0.0);
    EXPECT_EQ(dark.flareScale, 0.f);
    // Dim sky there: its own small flux, far below the light's.
    Image sky = background(320, 180, 0.1f);
    blob(sky, 200.f, 60.f, 4.f, 3000.f);
    EXPECT_LT(measureLightAt(sky, {40.f, 150.f}).flareScale,
              1e-3f * measureLightAt(sky, {200.f, 60.f}).flareScale);
    // Beyond the reach outside the frame (2% of 180 is 3.6, at least 4 px): nothing.
    for (const Point outside : {Point{-10.f, 50.f}, Point{400.f, 90.f}, Point{100.f, 184.5f}}) {
        const LightCandidate off = measureLightAt(img, outside);
        EXPECT_EQ(off.flux, 0.0);
        EXPECT_EQ(off.flareScale, 0.f);
    }
}

// A sun straddling the frame's left edge, its placed light walked from inside the frame out
// past the reach in 0.25 px steps: the flare scale never jumps between neighbouring positions
// (before, 0.0008 at x = 0 and 1.0 at x = -0.5), and fades to nothing.
TEST(MeasureLightAt, ALightWalkingAcrossTheEdgeNeverJumps) {
    Image img = background(320, 180, 0.2f);
    blob(img, 1.f, 90.f, 3.f, 5000.f);
    const float inside = measureLightAt(img, {1.f, 90.f}).flareScale;
    ASSERT_GT(inside, 0.f);
    float previous = inside, biggestStep = 0.f;
    for (float x = 1.f; x >= -6.f; x -= 0.25f) {
        const float scale = measureLightAt(img, {x, 90.f}).flareScale;
        EXPECT_LE(scale, inside * 1.001f) << x;
        biggestStep = std::max(biggestStep, std::abs(scale - previous));
        previous = scale;
    }
    // A 4 px fade walked in 0.25 px steps: at most a 16th of the light plus the smoothstep's
    // steepest slope (1.5x) per step.
    EXPECT_LE(biggestStep, inside * 1.5f / 16.f + 1e-6f);
    EXPECT_EQ(previous, 0.f);
    // Just outside, the light is still the sun's (not the preset's own 1 or nothing).
    EXPECT_NEAR(measureLightAt(img, {-0.25f, 90.f}).flareScale, inside, 0.05f * inside);
}
