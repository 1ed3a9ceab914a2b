// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/Parallel.h"
#include "flarekit/Elements.h"
#include "flarekit/Flare.h"

using namespace flarekit;

namespace {

Preset single(ElementType type, float t, float size) {
    Preset p;
    p.name = "test";
    ElementParams e = defaultElement(type);
    e.t = t;
    e.size = size;
    e.softness = 0.f;
    e.color = {1.f, 1.f, 1.f};
    e.innerColor.reset();
    e.intensity = 1.f;
    p.elements.push_back(e);
    return p;
}

Point centroid(const Image& img, double* total = nullptr) {
    double sx = 0, sy = 0, s = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const double v = img.at(x, y).r;
            sx += v * (x + 0.5);
            sy += v * (y + 0.5);
            s += v;
        }
    }
    if (total) *total = s;
    return {float(sx / s), float(sy / s)};
}

}  // namespace

TEST(FlareVector, PlacesElementsOnTheLineThroughTheCentre) {
    const Point light{500.f, 100.f};
    const Point at1 = flareVectorPoint(light, 640, 360, 1.f);
    const Point at0 = flareVectorPoint(light, 640, 360, 0.f);
    const Point mirrored = flareVectorPoint(light, 640, 360, -1.f);
    const Point half = flareVectorPoint(light, 640, 360, -0.5f);
    EXPECT_FLOAT_EQ(at1.x, 500.f);
    EXPECT_FLOAT_EQ(at1.y, 100.f);
    EXPECT_FLOAT_EQ(at0.x, 320.f);
    EXPECT_FLOAT_EQ(at0.y, 180.f);
    EXPECT_FLOAT_EQ(mirrored.x, 140.f);  // Tanczos 1999: (-h, -k)
    EXPECT_FLOAT_EQ(mirrored.y, 260.f);
    EXPECT_FLOAT_EQ(half.x, 320.f - 90.f);  // (-h/2, -k/2)
    EXPECT_FLOAT_EQ(half.y, 180.f + 40.f);
}

TEST(Flare, ElementLandsWhereTheVectorSays) {
    for (float t : {1.f, -1.f, -0.5f, 1.f / 3.2f}) {
        Image img(640, 360);
        renderFlare(img, single(ElementType::Disc, t, 0.05f), {470.3f, 91.7f}, 1.f);
        const Point want = flareVectorPoint({470.3f, 91.7f}, 640, 360, t);
        const Point got = centroid(img);
        EXPECT_NEAR(got.x, want.x, 0.05) << t;
        EXPECT_NEAR(got.y, want.y, 0.05) << t;
    }
}

TEST(Flare, CostIsThePixelsTheElementsCover) {
    Image img(1920, 1080);
    const FlareStats stats =
        renderFlare(img, single(ElementType::Disc, 1.f, 0.02f), {960.f, 540.f}, 1.f);
    EXPECT_EQ(stats.elementsDrawn, 1u);
    const double r = 0.02 * 1080;
    EXPECT_LE(double(stats.pixelsShaded), (2 * r + 6) * (2 * r + 6));
    EXPECT_GE(double(stats.pixelsShaded), 4 * r * r);
}

TEST(Flare, IntensityScalesLinearlyAndAddsToTheImage) {
    Image a(320, 200), b(320, 200);
    a.fill({0.1f, 0.2f, 0.3f, 1.f});
    b.fill({0.1f, 0.2f, 0.3f, 1.f});
    const Preset p = single(ElementType::Glow, 1.f, 0.3f);
    renderFlare(a, p, {160.f, 100.f}, 1.f);
    renderFlare(b, p, {160.f, 100.f}, 3.f);
    double ea = 0, eb = 0;
    for (int y = 0; y < 200; ++y) {
        for (int x = 0; x < 320; ++x) {
            ea += a.at(x, y).r - 0.1;
            eb += b.at(x, y).r - 0.1;
            ASSERT_EQ(a.at(x, y).a, 1.f);
        }
    }
    EXPECT_NEAR(eb / ea, 3.0, 1e-4);
}

TEST(Flare, LightOutsideTheFrameStillPutsGhostsOnScreen) {
    Image img(640, 360);
    const FlareStats stats =
        renderFlare(img, single(ElementType::Disc, -0.3f, 0.05f), {-400.f, -300.f}, 1.f);
    EXPECT_EQ(stats.elementsDrawn, 1u);
    double total = 0;
    centroid(img, &total);
    EXPECT_GT(total, 100.0);
    // A light absurdly far away must not overflow anything.
    Image far(64, 64);
    renderFlare(far, single(ElementType::Disc, 1.f, 0.1f), {1e30f, -1e30f}, 1.f);
    EXPECT_EQ(far.at(10, 10).r, 0.f);
}

TEST(Flare, ResultDoesNotDependOnThreadCount) {
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok()) << preset.error().message;
    Image one(800, 450), many(800, 450);
    {
        ThreadLimit limit(1);
        renderFlare(one, *preset, {600.f, 120.f}, 1.f);
    }
    renderFlare(many, *preset, {600.f, 120.f}, 1.f);
    EXPECT_EQ(0, std::memcmp(one.data(), many.data(), one.pixelCount() * sizeof(Rgba)));
}

TEST(Flare, TinyAndZeroSizedElementsAreSkippedSafely) {
    Image img(100, 100);
    const FlareStats stats =
        renderFlare(img, single(ElementType::Glow, 1.f, 0.f), {50.f, 50.f}, 1.f);
    EXPECT_EQ(stats.elementsDrawn, 0u);
}

TEST(EdgeStreak, PlacementFollowsTheNearestEdgeAndFadesWithin) {
    // 640 x 360, reach 0.25 heights = 90 px on either side of the edge.
    const EdgePlacement centre = edgeStreakPlacement({320, 180}, 640, 360, 0.25f);
    EXPECT_EQ(centre.weight, 0.f);  // 180 px from the nearest edge: past the reach
    const EdgePlacement onRight = edgeStreakPlacement({640, 100}, 640, 360, 0.25f);
    EXPECT_EQ(onRight.weight, 1.f);
    EXPECT_EQ(onRight.rotationDeg, 90.f);
    EXPECT_EQ(onRight.centre.x, 640.f);
    EXPECT_EQ(onRight.centre.y, 100.f);
    const EdgePlacement outsideTop = edgeStreakPlacement({200, -45}, 640, 360, 0.25f);
    EXPECT_EQ(outsideTop.rotationDeg, 0.f);
    EXPECT_EQ(outsideTop.centre.x, 200.f);
    EXPECT_EQ(outsideTop.centre.y, 0.f);
    EXPECT_FLOAT_EQ(outsideTop.weight, 0.5f);  // half the reach: smoothstep's midpoint
    const EdgePlacement insideLeft = edgeStreakPlacement({45, 200}, 640, 360, 0.25f);
    EXPECT_FLOAT_EQ(insideLeft.weight, 0.5f);
    EXPECT_EQ(insideLeft.centre.x, 0.f);
    EXPECT_EQ(edgeStreakPlacement({-200, 100}, 640, 360, 0.25f).weight, 0.f);
}

TEST(EdgeStreak, TheFlareLeavesTheFrameWithTheLight) {
    Preset p;
    ElementParams e = defaultElement(ElementType::EdgeStreak);
    e.size = 0.2f;
    e.reach = 0.25f;
    p.elements = {e};
    const auto sum = [](const Image& image, int x0, int x1) {
        double s = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = x0; x < x1; ++x) s += image.at(x, y).r;
        return s;
    };
    Image centred(640, 360), leaving(640, 360), gone(640, 360);
    renderFlare(centred, p, {320, 180}, 1.f);
    renderFlare(leaving, p, {660, 180}, 1.f);  // 20 px past the right edge
    renderFlare(gone, p, {800, 180}, 1.f);     // past the reach
    EXPECT_EQ(sum(centred, 0, 640), 0.0);
    EXPECT_GT(sum(leaving, 600, 640), 0.0);  // along the right edge...
    EXPECT_EQ(sum(leaving, 0, 500), 0.0);    // ...and only there: a vertical streak
    EXPECT_EQ(sum(gone, 0, 640), 0.0);
}
