// SPDX-License-Identifier: Apache-2.0
// The GPU methods' working textures as the studio's diagnostic panels read them
// (GpuVisibility::views): what they hold must be what the method's coverage came from.
#include <gtest/gtest.h>

#include "GlTestContext.h"
#include "OcclusionScenes.h"
#include "flarekit/gl/GpuVisibility.h"

using namespace flarekit;

namespace {

Scene caseNamed(const std::string& name) {
    for (const auto& c : test::occlusionCases())
        if (c.name == name) return c.scene;
    ADD_FAILURE() << "no occlusion case " << name;
    return {};
}

struct Measured {
    double coverage = 0;
    std::vector<MethodView> views;
};

Measured measureWithViews(const std::string& method, const Scene& scene,
                          const std::string& variant = "circle") {
    test::glContext();
    RenderOptions render;
    render.shadows = false;
    auto renderer = SceneRenderer::create(scene, render);
    EXPECT_TRUE(renderer.ok());
    GpuVisibilityOptions options;
    options.textureMaskVariant = variant;
    auto m = createGpuVisibility(method, scene, options);
    EXPECT_TRUE(m.ok()) << (m ? "" : m.error().message);
    auto coverage = measureStillFrame(**m, *renderer, scene, 8);
    EXPECT_TRUE(coverage.ok());
    return {*coverage, (*m)->views()};
}

double channelSum(const Image& image, int channel) {
    double sum = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) sum += image.data()[4 * i + channel];
    return sum;
}

}  // namespace

// GPG2's square variant: one point per texel of a 16x16 8-bit map, so the intensity map is the
// map's sum exactly and the coverage is its red (visible) over its green (in the disc).
TEST(MethodViews, TextureMaskSunMapAndIntensityMapAreWhatTheCoverageIsMadeOf) {
    const Measured m = measureWithViews("texture-mask", caseNamed("half-box-r30-e4"), "square");
    ASSERT_EQ(m.views.size(), 2u);
    const Image& map = m.views[0].image;
    EXPECT_EQ(m.views[0].name, "sun map 16x16");
    ASSERT_EQ(map.width(), 16);
    ASSERT_EQ(map.height(), 16);
    const double visible = channelSum(map, 0), disc = channelSum(map, 1);
    EXPECT_GT(disc, 150);  // the disc fills the square map: pi/4 of 256 texels
    EXPECT_NEAR(visible / disc, m.coverage, 1e-6);
    EXPECT_NEAR(m.coverage, 0.5, 0.08);  // a box edge through the middle
    const Image& sum = m.views[1].image;
    EXPECT_EQ(m.views[1].name, "intensity map 1x1");
    EXPECT_FLOAT_EQ(sum.data()[0] * 255.f, float(visible));
    EXPECT_FLOAT_EQ(sum.data()[1] * 255.f, float(disc));
}

// Burnout: the mask, the 14x14 grid and its chain to one value, which the coverage resolves.
TEST(MethodViews, BurnoutShowsItsMaskGridAndChainDownToTheCoverage) {
    const Measured m = measureWithViews("burnout", caseNamed("half-box-r30-e4"));
    const std::vector<std::string> names = {"mask 56x56", "grid 14x14", "chain 8x8",
                                            "chain 4x4",  "chain 2x2",  "chain 1x1"};
    ASSERT_EQ(m.views.size(), names.size());
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(m.views[i].name, names[i]);
    const Image& mask = m.views[0].image;
    int zeros = 0, ones = 0;
    for (std::size_t i = 0; i < mask.pixelCount(); ++i) {
        const float r = mask.data()[4 * i];
        EXPECT_TRUE(r == 0.f || r == 1.f) << r;  // binary, as on the PSP
        (r == 0.f ? zeros : ones)++;
    }
    EXPECT_GT(zeros, 300);
    EXPECT_GT(ones, 300);
    const float* last = m.views.back().image.data();
    ASSERT_GT(last[1], 0.f);
    EXPECT_NEAR(last[0] / last[1], m.coverage, 1e-6);
    EXPECT_NEAR(m.coverage, 0.5, 0.08);
}

// Nothing drawn, nothing shown: a sun hidden by culling, and a method without textures.
TEST(MethodViews, NoneWhenNothingWasDrawnOrTheMethodKeepsNone) {
    EXPECT_TRUE(measureWithViews("texture-mask", caseNamed("hidden-r30-d0")).views.empty());
    EXPECT_TRUE(measureWithViews("query", caseNamed("half-box-r30-e4")).views.empty());
    EXPECT_EQ(measureWithViews("texture-mask", caseNamed("visible-r30-d0")).views.size(), 2u);
}
