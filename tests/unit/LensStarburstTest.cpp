// SPDX-License-Identifier: Apache-2.0
// The lens starburst (the iris's Fraunhofer pattern): smooth spikes at the default wavelengths,
// spikes ending inside the PSF grid, its share of the light, dirt and a pupil mask from a file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ShippedLens.h"
#include "flarekit/Lens.h"

using namespace flarekit;
#include "flarekit/Image.h"

namespace {

using test::shippedLens;

}  // namespace

// The starburst is drawn at 32 wavelengths by default: each wavelength's fringes fall elsewhere
// along a spike, so summed they leave a smooth spike, where 3 wavelengths leave beads. Measured
// as the spike's second differences along the row through the light (a six-bladed iris has a
// horizontal spike), relative to its brightness.
TEST(Lens, TheDefaultStarburstIsSmoothAlongItsSpikes) {
    auto lens = loadLens("asahi-takumar-50");
    ASSERT_TRUE(lens.ok());
    const auto roughness = [&](int wavelengths) {
        LensRenderOptions o;
        o.ghosts = 0, o.glare = 0, o.starburst = 0.1, o.starburstSize = 0.3;
        o.starburstSamples = wavelengths;
        LensLight light;
        light.x = 200.5, light.y = 200.5;
        light.energy = {1e4, 1e4, 1e4};
        auto layers = renderLensFlare(*lens, 400, 400, {light}, o);
        EXPECT_TRUE(layers.ok());
        if (!layers.ok()) return 0.0;
        double bends = 0, level = 0;
        for (int x = 215; x < 320; ++x) {
            const auto g = [&](int px) { return double(layers->starburst.at(px, 200).g); };
            bends += std::abs(g(x + 1) - 2 * g(x) + g(x - 1));
            level += g(x);
        }
        return bends / level;
    };
    EXPECT_EQ(LensRenderOptions{}.starburstSamples, 32);
    const double beaded = roughness(3), smooth = roughness(32);
    EXPECT_GT(beaded, 0.0);
    EXPECT_LT(smooth, 0.35 * beaded) << "3: " << beaded << ", 32: " << smooth;
}

// The spikes end alike in every direction, inside the PSF's grid: nothing is drawn past 0.9 of
// the grid's half size at the longest wavelength, where a spike met the square's edge at a
// distance set by its direction and its tail wrapped round as a hooked tip.
TEST(Lens, StarburstSpikesEndInsideTheGridWithoutWrappedTips) {
    auto lens = loadLens("asahi-takumar-50");
    ASSERT_TRUE(lens.ok());
    LensRenderOptions o;
    o.ghosts = 0, o.glare = 0, o.starburst = 0.1, o.starburstSize = 0.2;
    LensLight light;
    light.x = 200.5, light.y = 200.5;
    light.energy = {1e4, 1e4, 1e4};
    auto layers = renderLensFlare(*lens, 400, 400, {light}, o);
    ASSERT_TRUE(layers.ok());
    // The grid's half size is the 550 nm radius; the longest sampled wavelength is just under
    // 700 nm.
    const double radius = 0.2 * std::hypot(400.0, 400.0), reach = 0.9 * radius * 700.0 / 550.0;
    double inside = 0, outside = 0;
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 400; ++x) {
            const double v = layers->starburst.at(x, y).g;
            (std::hypot(x + 0.5 - light.x, y + 0.5 - light.y) > reach + 1 ? outside : inside) += v;
        }
    EXPECT_GT(inside, 0.0);
    EXPECT_EQ(outside, 0.0);
}

TEST(Lens, StarburstCarriesItsShareAndDirtChangesOnlyItsPattern) {
    const Lens lens = shippedLens("angenieux-double-gauss");
    LensLight light;
    light.x = 200, light.y = 200;
    light.energy = {1000, 2000, 3000};
    const auto starburst = [&](double dirt, std::uint32_t seed) {
        LensRenderOptions o;
        o.ghosts = 0, o.glare = 0, o.starburst = 0.1, o.starburstSize = 0.2;
        o.dirt = dirt, o.dirtSeed = seed;
        auto layers = renderLensFlare(lens, 400, 400, {light}, o);
        EXPECT_TRUE(layers.ok());
        return layers.ok() ? layers->starburst : Image();
    };
    const auto sums = [](const Image& image) {
        std::array<double, 3> s{};
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const Rgba& p = image.at(x, y);
                s[0] += p.r, s[1] += p.g, s[2] += p.b;
            }
        return s;
    };
    // The PSF integrates to 1, so the layer holds the share of each channel's energy (the
    // pattern reaches 0.2 x 700 / 550 of the diagonal: inside the frame, bar its faint tails).
    const Image clean = starburst(0, 1), dusty = starburst(1, 7), again = starburst(1, 7);
    const auto c = sums(clean), d = sums(dusty);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(c[std::size_t(k)], 0.1 * light.energy[std::size_t(k)],
                    0.02 * 0.1 * light.energy[std::size_t(k)]);
        EXPECT_NEAR(d[std::size_t(k)], 0.1 * light.energy[std::size_t(k)],
                    0.05 * 0.1 * light.energy[std::size_t(k)]);
    }
    double differs = 0;
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 400; ++x) {
            differs += std::fabs(clean.at(x, y).g - dusty.at(x, y).g);
            EXPECT_EQ(dusty.at(x, y).g, again.at(x, y).g);  // same seed, same dirt
        }
    EXPECT_GT(differs, 0.05 * c[1]);
}

TEST(Lens, APupilMaskFromAnImageShapesTheStarburstAndKeepsItsShare) {
    // The user's own iris-plane image multiplies the iris. A clear (white) one changes nothing;
    // a horizontal slit, narrow in y, spreads the diffraction pattern in y (Fraunhofer: a
    // pattern's extent goes inversely with the aperture's), and the layer still carries its
    // share of the light.
    const Lens lens = shippedLens("angenieux-double-gauss");
    LensLight light;
    light.x = 200, light.y = 200;
    light.energy = {1000, 1000, 1000};
    const auto starburst = [&](std::shared_ptr<const Image> mask) {
        LensRenderOptions o;
        o.ghosts = 0, o.glare = 0, o.starburst = 0.1, o.starburstSize = 0.2;
        o.pupilMask = std::move(mask);
        auto layers = renderLensFlare(lens, 400, 400, {light}, o);
        EXPECT_TRUE(layers.ok());
        return layers.ok() ? layers->starburst : Image();
    };
    auto white = std::make_shared<Image>(64, 64);
    white->fill({1, 1, 1, 1});
    auto slit = std::make_shared<Image>(64, 64);
    for (int y = 28; y < 36; ++y)
        for (int x = 0; x < 64; ++x) slit->at(x, y) = {1, 1, 1, 1};
    const Image clean = starburst(nullptr), clear = starburst(white), slitted = starburst(slit);
    double sum = 0, xx = 0, yy = 0;
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 400; ++x) {
            EXPECT_EQ(clear.at(x, y).g, clean.at(x, y).g);
            const double v = slitted.at(x, y).g;
            sum += v, xx += v * (x + 0.5 - light.x) * (x + 0.5 - light.x),
                yy += v * (y + 0.5 - light.y) * (y + 0.5 - light.y);
        }
    EXPECT_NEAR(sum, 0.1 * light.energy[1], 0.05 * 0.1 * light.energy[1]);
    EXPECT_GT(yy, 4 * xx) << "the slit's pattern spreads across it";
}

// ghostsOnImage says where each drawn ghost is (the studio's ghost picking). On axis every ghost
// is centred on the image centre (the lens is rotationally symmetric); off axis a ghost drawn
// alone has its light-weighted centroid where it says, within a tenth of its radius (the
// analyser's landing-ray centroid against the renderer's meshes).
TEST(Lens, GhostsOnImageAreWhereTheRendererDrawsThem) {
    auto lens = loadLens("angenieux-double-gauss");
    ASSERT_TRUE(lens.ok());
    auto onAxis = ghostsOnImage(*lens, 400, 300, {200.f, 150.f}, 8);
    ASSERT_TRUE(onAxis.ok()) << onAxis.error().message;
    ASSERT_EQ(onAxis->size(), 8u);
    for (const GhostOnImage& g : *onAxis) {
        EXPECT_NEAR(g.x, 200.0, 0.5) << g.first << "-" << g.second;
        EXPECT_NEAR(g.y, 150.0, 0.5) << g.first << "-" << g.second;
        EXPECT_GT(g.first, g.second);
    }
    const Point at{300.5f, 90.5f};
    auto ghosts = ghostsOnImage(*lens, 400, 300, at, 8);
    ASSERT_TRUE(ghosts.ok() && ghosts->size() == 8);
    // The most compact of them inside the frame, drawn alone: the render of the k brightest
    // less the render of the k - 1 brightest (ghosts add).
    std::size_t k = 0;
    for (std::size_t i = 1; i < ghosts->size(); ++i) {
        const GhostOnImage& c = (*ghosts)[i];
        const bool inside = c.x - c.radius > 0 && c.x + c.radius < 400 && c.y - c.radius > 0 &&
                            c.y + c.radius < 300;
        if (inside && (k == 0 || c.radius < (*ghosts)[k].radius)) k = i;
    }
    ASSERT_GT(k, 0u) << "no ghost wholly inside the frame";
    const GhostOnImage& g = (*ghosts)[k];
    const auto render = [&](int n) {
        LensRenderOptions o;
        o.ghosts = n, o.glare = 0, o.starburst = 0;
        LensLight light;
        light.x = at.x, light.y = at.y, light.energy = {1e4, 1e4, 1e4};
        auto layers = renderLensFlare(*lens, 400, 300, {light}, o);
        EXPECT_TRUE(layers.ok());
        return layers.ok() ? layers->ghosts : Image(400, 300);
    };
    const Image with = render(int(k) + 1), without = render(int(k));
    double sum = 0, cx = 0, cy = 0;
    for (int y = 0; y < 300; ++y)
        for (int x = 0; x < 400; ++x) {
            const Rgba &p = with.at(x, y), &q = without.at(x, y);
            const double w = std::max(0.0, double(p.r + p.g + p.b) - double(q.r + q.g + q.b));
            sum += w, cx += w * (x + 0.5), cy += w * (y + 0.5);
        }
    ASSERT_GT(sum, 0);
    EXPECT_NEAR(cx / sum, g.x, 0.1 * g.radius + 1.0) << g.first << "-" << g.second;
    EXPECT_NEAR(cy / sum, g.y, 0.1 * g.radius + 1.0) << g.first << "-" << g.second;
}
