// SPDX-License-Identifier: Apache-2.0
// The CPU draws that skip work: the ghosts and the halo leave out the taps that cannot read
// light above their threshold, and resizeBilinear filters separably. Each must write what its
// per-pixel kernel (the GLSL twin's line-for-line copy) writes, bit for bit, on sparse light
// (a lamp inside, one on an edge, one in a corner), on dense light and on none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "flarekit/PostFx.h"
#include "flarekit/PostFxParams.h"
#include "postfx/ghosts/Ghosts.h"
#include "postfx/halo/Halo.h"

namespace flarekit {
namespace {

using postfx::F4;

bool sameBits(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), a.pixelCount() * 4 * sizeof(float)) == 0;
}

//! A bloom buffer with a few lamps of falling light over black, or dense light everywhere.
Image bloomBuffer(int w, int h, const std::vector<std::pair<int, int>>& lamps, bool dense) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rgba& p = image.at(x, y);
            if (dense)
                p = {0.3f + 0.2f * std::sin(0.3f * float(x)), 0.4f, 0.1f * float(y % 7), 1.f};
            for (auto [lx, ly] : lamps) {
                const float d2 = float((x - lx) * (x - lx) + (y - ly) * (y - ly));
                const float v = d2 > 16.f ? 0.f : 40.f / (1.f + d2);
                p.r += v, p.g += 0.7f * v, p.b += 0.4f * v;
            }
        }
    return image;
}

struct Case {
    const char* name;
    std::vector<std::pair<int, int>> lamps;
    bool dense;
};

const std::vector<Case>& cases(int w, int h) {
    static const std::vector<Case> all = {
        {"one lamp inside", {{w / 3, h / 4}}, false},
        {"lamps on an edge and in a corner", {{0, h / 2}, {w - 1, h - 1}}, false},
        {"dense light", {{w / 2, h / 2}}, true},
        {"no light", {}, false},
    };
    return all;
}

template <class Uniforms>
void expectDrawIsKernel(const Uniforms& u, const Image& bloom, int w, int h, const char* what) {
    const postfx::Tex in[1] = {postfx::Tex(bloom)};
    Image expected(w, h), drawn(w, h);
    postfx::runPass(expected, [&](int x, int y) { return postfx::passPixel(u, in, x, y); });
    postfx::drawPass(u, in, drawn);
    EXPECT_TRUE(sameBits(expected, drawn)) << what;
}

TEST(SparseDraws, TheGhostsDrawIsItsPixelKernelBitForBit) {
    const int w = 97, h = 61;  // odd sizes: a pixel at the exact centre, uneven texels
    std::vector<GhostParams> ghosts;
    for (float scale : {1.f, -2.5f, 0.4f, 3.2f}) {
        GhostParams g;
        g.scale = scale, g.blur = scale > 3 ? 2.f : 0.05f, g.samples = scale < 0 ? 5 : 12;
        g.threshold = scale == 1.f ? 0.f : 0.05f;
        g.centered = scale > 0.5f, g.linearFilter = scale != 0.4f, g.falloff = 3;
        g.tint = {0.9f, 0.5f, 0.3f};
        ghosts.push_back(g);
    }
    ghosts.push_back(ghosts[1]);  // the same threshold as the ghost before it shares its scan
    for (const Case& c : cases(w, h)) {
        const Image bloom = bloomBuffer(w, h, c.lamps, c.dense);
        const postfx::Vec2 inv = postfx::inverseSize(w, h);
        expectDrawIsKernel(postfx::ghostsUniforms(inv, inv, ghosts, 0.8f), bloom, w, h, c.name);
    }
}

TEST(SparseDraws, TheHaloDrawIsItsPixelKernelBitForBit) {
    const int w = 97, h = 61;
    for (const Case& c : cases(w, h)) {
        const Image bloom = bloomBuffer(w, h, c.lamps, c.dense);
        for (float threshold : {0.f, 0.1f}) {
            HaloParams halo;
            halo.radius = 0.65f, halo.thickness = 0.12f, halo.threshold = threshold;
            halo.falloff = 5, halo.tint = {0.9f, 0.8f, 1.f};
            const postfx::HaloUniforms u{postfx::inverseSize(w, h), float(w) / float(h), halo,
                                         0.3f};
            expectDrawIsKernel(u, bloom, w, h, c.name);
        }
    }
}

// A sparse frame is where the draws skip: check that they do skip (so the tests above compare
// a path that leaves work out), by the share of output pixels the lamp's ghost can reach.
TEST(SparseDraws, ALampsGhostReachesOnlyTheRegionAroundItsMirrorPoint) {
    const int w = 128, h = 128;
    const Image bloom = bloomBuffer(w, h, {{20, 30}}, false);
    const postfx::Tex tex(bloom);
    const postfx::HotTexels hot(tex, 0.05f);
    int reached = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const postfx::Vec2 uv = postfx::pixelUv(x, y, postfx::inverseSize(w, h));
            const postfx::Vec2 at = postfx::texelCoord(tex, {1.f - uv.x, 1.f - uv.y});  // scale 1
            reached += !hot.misses(at, at);
        }
    // Light above 0.05 lies within 4 texels of the lamp: a 9 x 9 patch, reachable from an
    // 11 x 11 block of mirrored pixels (a bilinear tap reads one texel either side).
    EXPECT_EQ(reached, 11 * 11);
}

TEST(SparseDraws, ResizeBilinearIsTheBilinearKernelAtEveryPixel) {
    for (auto [src, dst] : {std::pair{std::pair{128, 72}, std::pair{512, 288}},
                            std::pair{std::pair{33, 17}, std::pair{131, 67}},
                            std::pair{std::pair{64, 48}, std::pair{20, 13}},
                            std::pair{std::pair{1, 1}, std::pair{9, 7}}}) {
        const Image source = bloomBuffer(src.first, src.second, {{src.first / 2, 0}}, true);
        const postfx::Tex tex(source);
        Image expected(dst.first, dst.second);
        const postfx::Vec2 inv = postfx::inverseSize(dst.first, dst.second);
        postfx::runPass(expected, [&](int x, int y) {
            return postfx::bilinear(tex, postfx::pixelUv(x, y, inv));
        });
        EXPECT_TRUE(sameBits(expected, resizeBilinear(source, dst.first, dst.second)))
            << src.first << "x" << src.second << " -> " << dst.first << "x" << dst.second;
    }
}

// A caller that adds the flare itself (the flare-data generator) stops the chain at the lens
// buffer: the layers are those of a full run, and no composite is drawn.
TEST(SparseDraws, AChainWithoutItsCompositeGivesTheSameLayersAndNoFinal) {
    Image input = bloomBuffer(160, 90, {{40, 30}}, false);
    for (int i = 0; i < 160 * 90; ++i) input.data()[4 * i + 3] = 1.f;
    auto params = loadPostFxPreset("modern");
    ASSERT_TRUE(params.ok());
    PostFxOptions full, layersOnly;
    full.keepLayers = layersOnly.keepLayers = true;
    layersOnly.composite = false;
    auto a = postFxCpu(input, *params, full), b = postFxCpu(input, *params, layersOnly);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->final.width(), 160);
    EXPECT_TRUE(b->final.empty());
    EXPECT_TRUE(sameBits(a->lens, b->lens));
    EXPECT_TRUE(sameBits(a->ghosts, b->ghosts));
    EXPECT_TRUE(sameBits(a->halo, b->halo));
    float peak = 0.f;
    for (std::size_t i = 0; i < b->lens.pixelCount() * 4; ++i)
        peak = std::max(peak, b->lens.data()[i]);
    EXPECT_GT(peak, 0.f);  // the lamp flared
}

}  // namespace
}  // namespace flarekit
