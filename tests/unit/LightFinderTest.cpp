#include <gtest/gtest.h>

#include <cmath>

#include "flarekit/Flare.h"

using namespace flarekit;

namespace {
void blob(Image& img, float cx, float cy, float radius, float value) {
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            if (std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy) < radius)
                img.at(x, y) = {value, value, value, 1.f};
        }
    }
}
}  // namespace

TEST(LightFinder, FindsTheCentroidOfTheBrightestRegion) {
    Image img(400, 300);
    img.fill({0.1f, 0.1f, 0.1f, 1.f});
    blob(img, 250.5f, 80.25f, 9.f, 1.f);
    const FoundLight light = findLight(img);
    ASSERT_TRUE(light.found);
    EXPECT_NEAR(light.position.x, 250.5f, 0.1f);
    EXPECT_NEAR(light.position.y, 80.25f, 0.1f);
    EXPECT_NEAR(light.brightness, 1.f, 1e-5f);
    EXPECT_NEAR(light.flareScale, 1.f, 1e-5f);
}

TEST(LightFinder, PicksTheRegionWithTheMostLightNotTheMidpoint) {
    Image img(400, 300);
    blob(img, 60.f, 60.f, 4.f, 1.f);       // small
    blob(img, 300.f, 200.f, 12.f, 0.98f);  // large, almost as bright
    const FoundLight light = findLight(img);
    ASSERT_TRUE(light.found);
    EXPECT_NEAR(light.position.x, 300.f, 0.5f);
    EXPECT_NEAR(light.position.y, 200.f, 0.5f);
}

TEST(LightFinder, NoLightInADimImage) {
    Image img(64, 64);
    img.fill({0.2f, 0.2f, 0.2f, 1.f});
    EXPECT_FALSE(findLight(img).found);
    EXPECT_FALSE(findLight(Image(64, 64)).found);  // black
}

TEST(LightFinder, HdrLightsScaleLogarithmicallyAboveWhite) {
    Image img(64, 64);
    blob(img, 32.f, 32.f, 5.f, 50.f);
    const FoundLight light = findLight(img);
    ASSERT_TRUE(light.found);
    EXPECT_NEAR(light.brightness, 50.f, 1e-3f);
    EXPECT_NEAR(light.flareScale, 1.f + std::log(50.f), 1e-4f);
    Image dim(64, 64);
    blob(dim, 32.f, 32.f, 5.f, 0.6f);
    EXPECT_NEAR(findLight(dim).flareScale, 0.6f, 1e-5f);
}
