// SPDX-License-Identifier: Apache-2.0
// --light auto: which regions are lights, where they are and how much flux they carry. Fluxes
// are summed here from the images the tests draw, not taken from flarekit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

#include "core/RadixSort.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"

using namespace flarekit;

namespace {

//! A disc of `value`, plus (glare > 0) a glow around it falling as glare / (1 + 4 u^2), u the
//! distance past the rim in radii, the way a lens's veiling glare spreads a clipped light.
void blob(Image& img, float cx, float cy, float radius, float value, float glare = 0.f) {
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

Image background(int w, int h, float v) {
    Image img(w, h);
    img.fill({v, v, v, 1.f});
    return img;
}

double discFlux(const Image& img, float cx, float cy, float radius) {
    double sum = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            if (std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy) < radius)
                sum += img.at(x, y).r;
    return sum;
}

}  // namespace

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

// The seed order: the keys, made in raster order, grouped by their luminance half and each
// group sorted, are in the order of a plain descending sort of the whole keys (ties in raster
// order), on frames whose luminances tie a lot (8-bit steps), on ones that use every digit
// (random floats) and on one long tie (clipped white).
TEST(LightFinderSeeds, BucketsSortedOneByOneAreTheDescendingOrder) {
    std::mt19937 rng(11);
    const auto bitsOf = [](float l) {
        std::uint32_t bits;
        std::memcpy(&bits, &l, sizeof bits);
        return bits;
    };
    // 1,000 keys: one thread; 200,000: in slices on every core.
    for (const std::uint32_t count : {1000u, 200000u})
        for (const int kind : {0, 1, 2}) {
            SortKeys keys;
            const float top = kind == 1 ? 40000.f : 1.f;
            for (std::uint32_t i = 0; i < count; ++i) {
                float l = std::uniform_real_distribution<float>(0.25f, top)(rng);
                if (kind == 0) l = std::round(l * 255.f) / 255.f;
                if (kind == 2) l = 1.f;
                keys.push_back((std::uint64_t(bitsOf(l)) << 32) | (0xFFFFFFFFu - i));
            }
            SortKeys expected = keys;
            std::sort(expected.begin(), expected.end(), std::greater<>());
            HighBuckets buckets = bucketByHigh32Descending(keys, bitsOf(0.25f), bitsOf(top));
            ASSERT_LE(buckets.count(), 2048u);
            ASSERT_EQ(buckets.begin.front(), 0u);
            ASSERT_EQ(buckets.begin.back(), keys.size());
            for (std::size_t b = 0; b < buckets.count(); ++b)
                sortDescending(buckets.keys, buckets.begin[b], buckets.begin[b + 1]);
            EXPECT_EQ(buckets.keys, expected) << count << " " << kind;
            if (kind == 1) {
                EXPECT_GT(buckets.count(), 1000u);  // a span of 2^28: all 2048 used
            }
        }
    const HighBuckets none = bucketByHigh32Descending({}, 0, 100);
    EXPECT_EQ(none.count(), 1u);
    EXPECT_TRUE(none.keys.empty());
    const HighBuckets one = bucketByHigh32Descending({42}, 0, 0);
    EXPECT_EQ(one.keys, SortKeys{42});
    EXPECT_EQ(one.count(), 1u);
}

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

// One flare per physical light: a strip light found as bright spots 6 px apart (each its own
// peak) and a window found twice 16 px apart are one light each, with the summed flux at the
// flux-weighted centre; two lamps 60 px apart stay two.
TEST(LightFinder, SpotsOfOneStripOrWindowAreOneLightLampsApartAreTwo) {
    Image img = background(640, 360, 0.01f);
    const float spots[] = {200.f, 206.f, 212.f, 218.f};
    const float values[] = {3000.f, 2600.f, 2800.f, 2400.f};
    for (int i = 0; i < 4; ++i) blob(img, spots[i], 100.f, 1.5f, values[i]);
    blob(img, 420.f, 250.f, 5.f, 1500.f);  // a window's two panes
    blob(img, 436.f, 250.f, 5.f, 1200.f);
    blob(img, 560.f, 80.f, 2.f, 2000.f);  // two lamps 60 px apart
    blob(img, 620.f, 80.f, 2.f, 2000.f);
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

namespace {
//! A disc of colour `core` (flat: clipped, or not) with a soft glare of `glare` around it.
void colouredBlob(Image& img, float cx, float cy, float radius, Rgba core, float glare) {
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
}  // namespace

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
