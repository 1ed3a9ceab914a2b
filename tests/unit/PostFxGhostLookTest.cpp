// SPDX-License-Identifier: Apache-2.0
// How the post-process ghosts look on real frames: the border window (a ghost never draws the
// mirrored frame edge as a straight-edged slab) and the tint's saturation (a ghost takes the
// colour of what it samples). CPU vs GL parity of both is tests/gl/PostFxParityTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flarekit/Flare.h"
#include "flarekit/PostFx.h"
#include "flarekit/Tonemap.h"
#include "postfx/Kernel.h"
#include "postfx/ghosts/Ghosts.h"

namespace flarekit {
namespace {

using postfx::borderWindow;
using postfx::Vec2;

// The window is smoothstep(d / fade) in x times the same in y, d the distance to the nearer
// edge: exact values at the edge, the middle of the ramp and inside; fade 0 is the seed's cut.
TEST(PostFxBorderWindow, IsTheProductOfTwoSmoothstepsOverTheFade) {
    EXPECT_EQ(borderWindow({0.5f, 0.5f}, 0.125f), 1.f);
    EXPECT_EQ(borderWindow({0.125f, 0.875f}, 0.125f), 1.f);
    EXPECT_EQ(borderWindow({0.f, 0.5f}, 0.125f), 0.f);
    EXPECT_EQ(borderWindow({0.5f, 1.f}, 0.125f), 0.f);
    EXPECT_FLOAT_EQ(borderWindow({0.0625f, 0.5f}, 0.125f), 0.5f);       // smoothstep(1/2)
    EXPECT_FLOAT_EQ(borderWindow({0.5f, 0.96875f}, 0.125f), 0.15625f);  // smoothstep(1/4)
    EXPECT_FLOAT_EQ(borderWindow({0.0625f, 0.0625f}, 0.125f), 0.25f);   // both sides
    EXPECT_EQ(borderWindow({0.f, 0.f}, 0.f), 1.f);
    EXPECT_EQ(borderWindow({1.f, 0.3f}, 0.f), 1.f);
}

//! A chain of one ghost of `scale` alone: no bloom added, no ceiling, a compact bloom buffer,
//! one unblurred bilinear tap, no threshold; the ghost layer is kept.
PostFxParams oneGhost(float brightThreshold, float scale) {
    PostFxParams p;
    p.bright = {brightThreshold, 0.f};
    p.bright.ceiling = 0.f;
    p.bloom = {0.f, 2, 1.f};
    GhostParams g;
    g.scale = scale, g.blur = 0.f, g.samples = 1, g.threshold = 0.f, g.linearFilter = true;
    p.ghosts = {g};
    return p;
}

Image ghostLayer(const Image& in, const PostFxParams& p) {
    PostFxOptions o;
    o.keepLayers = true;
    auto r = postFxCpu(in, p, o);
    EXPECT_TRUE(r.ok());
    return r.ok() ? r->ghosts : Image{};
}

//! One magnifying ghost (scale 2: the buffer's border s = 0 lands at 3/4 of the frame) of a sky
//! that is brightest at the left frame edge and falls off linearly over 40% of the width.
Image ghostOfABrightEdge(float borderFade) {
    const int w = 320, h = 180;
    Image sky(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float v = 20.f * std::max(0.f, 1.f - (float(x) + 0.5f) / (0.4f * float(w)));
            sky.at(x, y) = {v, v, v, 1.f};
        }
    }
    PostFxParams p = oneGhost(1.f, 2.f);
    p.ghosts[0].borderFade = borderFade;
    return ghostLayer(sky, p);
}

//! The largest step between neighbours along the middle row, as a share of the row's peak.
double steepestStep(const Image& ghost) {
    const int y = ghost.height() / 2;
    double peak = 0, step = 0;
    for (int x = 0; x < ghost.width(); ++x) {
        peak = std::max(peak, double(ghost.at(x, y).g));
        if (x > 0) step = std::max(step, std::abs(double(ghost.at(x, y).g - ghost.at(x - 1, y).g)));
    }
    return peak > 0 ? step / peak : 0;
}

// The slab: at fade 0 (the seed) the ghost stops dead where its taps leave the buffer, a cut
// of its full height in one texel; with the default window the same ghost eases out, no step
// steeper than the ramp's own smoothstep slope (1.5 / fade per buffer width).
TEST(PostFxBorderWindow, AMagnifiedGhostOfABrightEdgeHasNoHardCut) {
    const Image seed = ghostOfABrightEdge(0.f);
    const Image windowed = ghostOfABrightEdge(kDefaultBorderFade);
    ASSERT_GT(seed.width(), 0);
    ASSERT_GT(windowed.width(), 0);
    EXPECT_GT(steepestStep(seed), 0.6);
    // Two texels of buffer per ghost texel at scale 2: 1.5 / 0.125 x 2 / width, plus rounding.
    const double ramp = 1.5 / kDefaultBorderFade * 2.0 / windowed.width();
    EXPECT_LT(steepestStep(windowed), 1.3 * ramp);
    EXPECT_GT(steepestStep(windowed), 0.0);
}

//! The ghost layer's energy per channel for a warm lamp and one purple-tinted ghost.
Rgb ghostColour(float saturation) {
    Image lamp(256, 144);
    lamp.fill({0.f, 0.f, 0.f, 1.f});
    for (int y = 60; y < 68; ++y)
        for (int x = 160; x < 168; ++x) lamp.at(x, y) = {8.f, 4.f, 1.f, 1.f};
    PostFxParams p = oneGhost(0.5f, 1.f);
    p.ghosts[0].tint = {0.7f, 0.2f, 0.9f};  // the seed's purple ghost
    p.ghosts[0].saturation = saturation;
    const Image ghosts = ghostLayer(lamp, p);
    Rgb sum{0.f, 0.f, 0.f};
    for (std::size_t i = 0; i < ghosts.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) sum[c] += ghosts.data()[4 * i + c];
    return sum;
}

// saturation 0: the ghost is the lamp's own colour (its channel ratios exactly: the bright pass
// scales a pixel by its luminance's excess, keeping its hue, and the bloom is linear);
// 1: lamp x the seed's tint.
TEST(PostFxGhostTint, SaturationZeroKeepsTheColourOfWhatTheGhostSamples) {
    const Rgb grey = ghostColour(0.f);
    ASSERT_GT(grey[1], 0.f);
    EXPECT_NEAR(grey[0] / grey[1], 8.f / 4.f, 1e-4);
    EXPECT_NEAR(grey[2] / grey[1], 1.f / 4.f, 1e-4);
    const Rgb seed = ghostColour(1.f);
    ASSERT_GT(seed[1], 0.f);
    EXPECT_NEAR(seed[0] / seed[1], (8.f * 0.7f) / (4.f * 0.2f), 1e-3);
}

// The tint keeps its luminance at every saturation; at 1 it is the seed's vTint bit for bit.
TEST(PostFxGhostTint, TheTintKeepsItsLuminance) {
    GhostParams g;
    g.tint = {0.7f, 0.2f, 0.9f};
    const auto luma = [](const Rgb& t) {
        return postfx::kLumaR * t[0] + postfx::kLumaG * t[1] + postfx::kLumaB * t[2];
    };
    for (float s : {0.f, 0.25f, 0.5f, 1.f}) {
        g.saturation = s;
        EXPECT_NEAR(luma(postfx::ghostTint(g)), luma(g.tint), 1e-6f) << s;
    }
    g.saturation = 1.f;
    EXPECT_EQ(postfx::ghostTint(g), g.tint);
    g.saturation = 0.f;
    const Rgb grey = postfx::ghostTint(g);
    EXPECT_FLOAT_EQ(grey[0], grey[1]);
    EXPECT_FLOAT_EQ(grey[1], grey[2]);
}

// A ghost magnified 1 / |scale| times carries scale^2 of the seed's energy density, so its
// total energy is what the unmagnified ghost's is (the same light over a larger area); a
// minified ghost (|scale| > 1) is left as the seed draws it.
TEST(PostFxGhostTint, AMagnifiedGhostIsDimmedByTheAreaItSpreadsOver) {
    GhostParams g;
    g.tint = {0.7f, 0.2f, 0.9f};
    g.saturation = 1.f;
    for (const float scale : {0.5f, -0.25f, 2.f}) {
        g.scale = scale;
        g.conserveArea = false;
        const Rgb seed = postfx::ghostTint(g);
        g.conserveArea = true;
        const Rgb dimmed = postfx::ghostTint(g);
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(dimmed[c], seed[c] * std::min(1.f, scale * scale)) << scale;
    }
}

// --expand-highlights expands the lights of an 8-bit frame, not its near-white plateaus: a
// clipped sun with glare (a light to the finder) gets `gain` x white at its core; a snowfield
// at 0.95 (sRGB 250, bright but no light: no core at the file's white) keeps its pixels bit for
// bit, where the ungated curve would lift it by half the gain.
TEST(PostFxExpand, OnlyTheLightsOfAnEightBitFrameAreExpanded) {
    const int w = 320, h = 180;
    Image photo(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float dx = float(x) + 0.5f - 240.f, dy = float(y) + 0.5f - 50.f;
            const float d = std::sqrt(dx * dx + dy * dy);
            float v =
                0.25f + 0.75f / (1.f + 0.02f * std::max(0.f, d - 6.f) * std::max(0.f, d - 6.f));
            if (d <= 6.f) v = 1.f;
            Rgba p{v, v, v, 1.f};
            if (y >= 120 && x < 200) p = {0.95f, 0.95f, 0.95f, 1.f};  // the snowfield
            photo.at(x, y) = p;
        }
    Image expanded = photo;
    const LightSearch search = expandHighlightsAtLights(expanded, 4.f);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    EXPECT_NEAR(search.lights[0].position.x, 240.f, 1.f);
    EXPECT_FLOAT_EQ(expanded.at(240, 50).g, 4.f);  // the clipped core: gain x white
    for (int y = 120; y < h; y += 7)
        for (int x = 0; x < 200; x += 9) ASSERT_EQ(expanded.at(x, y).g, 0.95f) << x << "," << y;
    Image everywhere = photo;
    expandHighlights(everywhere, 4.f);
    EXPECT_GT(everywhere.at(10, 150).g, 1.5f);  // what the plain curve does to the snow
}

}  // namespace
}  // namespace flarekit
