// SPDX-License-Identifier: Apache-2.0
// The post-process chain on the CPU: presets, the seed's geometry, linearity, edge cases.
// CPU vs GL parity is tests/gl/PostFxParityTest.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "PostFxImages.h"
#include "flarekit/PostFx.h"
#include "postfx/brightpass/BrightPass.h"
#include "postfx/composite/Composite.h"
#include "postfx/starburst/Starburst.h"
#include "postfx/streaks/Streaks.h"

namespace flarekit {
namespace {

using test::brightDot;

PostFxParams load(const std::string& name) {
    auto p = loadPostFxPreset(name);
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p.ok() ? *p : PostFxParams{};
}

//! One ghost, no bloom added, a compact bloom buffer (levels 2): the ghost alone, measurable.
PostFxParams singleGhost(float scale, float blur, int samples) {
    PostFxParams p;
    p.bright = {1.f, 0.f};
    p.bloom = {0.f, 2, 1.f};
    GhostParams g;
    g.scale = scale, g.blur = blur, g.samples = samples, g.threshold = 0.f, g.linearFilter = true;
    p.ghosts = {g};
    return p;
}

struct Moments {
    double sum = 0, x = 0, y = 0;  //!< energy and centroid in normalised [-1, 1] coordinates
};

Moments moments(const Image& img) {
    Moments m;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const Rgba& p = img.at(x, y);
            const double e = double(p.r) + p.g + p.b;
            m.sum += e;
            m.x += e * ((x + 0.5) / img.width() * 2 - 1);
            m.y += e * ((y + 0.5) / img.height() * 2 - 1);
        }
    }
    if (m.sum > 0) m.x /= m.sum, m.y /= m.sum;
    return m;
}

//! Standard deviation of the energy along the unit direction (dx, dy), normalised units.
double spreadAlong(const Image& img, const Moments& m, double dx, double dy) {
    double acc = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const Rgba& p = img.at(x, y);
            const double e = double(p.r) + p.g + p.b;
            const double t = ((x + 0.5) / img.width() * 2 - 1 - m.x) * dx +
                             ((y + 0.5) / img.height() * 2 - 1 - m.y) * dy;
            acc += e * t * t;
        }
    }
    return std::sqrt(acc / m.sum);
}

Result<PostFxResult> runLayers(const Image& in, const PostFxParams& p) {
    PostFxOptions o;
    o.keepLayers = true;
    return postFxCpu(in, p, o);
}

TEST(PostFxPresets, ShippedPresetsLoadAndKillzone2IsTheSeed) {
    const auto names = shippedPostFxPresetNames();
    for (const char* want : {"killzone2", "modern", "anamorphic", "subtle"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
        load(want);
    }
    const PostFxParams kz = load("killzone2");
    ASSERT_EQ(kz.ghosts.size(), 2u);
    const GhostParams& orange = kz.ghosts[0];
    const GhostParams& purple = kz.ghosts[1];
    EXPECT_EQ(orange.tint, (Rgb{0.7f, 0.4f, 0.2f}));
    EXPECT_FLOAT_EQ(orange.scale, 2.f);
    EXPECT_FLOAT_EQ(orange.blur, 0.15f);
    EXPECT_EQ(purple.tint, (Rgb{0.7f, 0.2f, 0.9f}));
    EXPECT_FLOAT_EQ(purple.scale, 0.5f);
    EXPECT_FLOAT_EQ(purple.blur, 0.1f);
    for (const GhostParams& g : kz.ghosts) {
        EXPECT_EQ(g.samples, 12);
        EXPECT_FLOAT_EQ(g.threshold, 0.1f);
        EXPECT_FALSE(g.linearFilter);  // the seed's PointSampler
        EXPECT_FALSE(g.centered);
        EXPECT_EQ(g.falloff, 0.f);
    }
    // CombinePS adds the bloom buffer as is (1); the preset halves it, so the seed's bloom of a
    // clipped 8-bit sun or a lit window stays within the budgets (docs/postfx.md).
    EXPECT_FLOAT_EQ(kz.bloom.intensity, 0.5f);
}

TEST(PostFxPresets, BadPresetsNameTheFieldAndWhatWasExpected) {
    const auto error = [](const std::string& text) {
        auto r = parsePostFxPreset(text, "p.json");
        return r.ok() ? std::string("(accepted)") : r.error().message;
    };
    EXPECT_EQ(
        error(R"({"bloom": {"intensty": 1}})")
            .rfind(
                "p.json: bloom.intensty: unknown key (expected one of: intensity, levels, spread)",
                0),
        0u);
    EXPECT_NE(error(R"({"bloom": {"levels": 1}})")
                  .find("bloom.levels: expected an integer in [2, 12], got 1"),
              std::string::npos);
    EXPECT_NE(error(R"({"ghosts": [{"tint": [1, 2]}]})")
                  .find("ghosts[0].tint: expected an array of 3 numbers"),
              std::string::npos);
    EXPECT_NE(
        error(R"({"ghosts": [{"scale": 0.01}]})").find("ghosts[0].scale: expected |scale| >= 0.05"),
        std::string::npos);
    EXPECT_NE(
        error(R"({"ghosts": [{"filter": "nearest"}]})").find("expected \"point\" or \"bilinear\""),
        std::string::npos);
    EXPECT_NE(error(R"({"tonemap": {"operator": "reinhard"}})").find("tonemap.operator"),
              std::string::npos);
    EXPECT_NE(error(R"({"flares": 1})").find("flares: unknown key"), std::string::npos);
    EXPECT_NE(error(R"({"bright": {"threshold": -1}})").find("bright.threshold"),
              std::string::npos);
    EXPECT_NE(error("{\"bloom\": ").find("invalid JSON"), std::string::npos);
    EXPECT_NE(error(R"({"ghost_series": {"spacing": 0.5}})").find("ghost_series.count: missing"),
              std::string::npos);
    // A series reaching scale 0 would spread one bloom texel over the frame: refused.
    EXPECT_NE(error(R"({"ghost_series": {"count": 4, "spacing": 0.5}})").find("ghost 2.scale"),
              std::string::npos);
    auto series = parsePostFxPreset(
        R"({"ghost_series": {"count": 3, "spacing": 0.3, "tints": [[1,0,0],[0,1,0]], "blur": 0.2}})",
        "s.json");
    ASSERT_TRUE(series.ok()) << series.error().message;
    ASSERT_EQ(series->ghosts.size(), 3u);
    EXPECT_FLOAT_EQ(series->ghosts[1].scale, 0.7f);
    EXPECT_EQ(series->ghosts[2].tint, (Rgb{1.f, 0.f, 0.f}));
    EXPECT_FLOAT_EQ(series->ghosts[2].blur, 0.2f);
    EXPECT_FALSE(loadPostFxPreset("no-such-preset").ok());
}

TEST(PostFxKernels, SoftKneeIsZeroBelowAndLinearAbove) {
    using postfx::F4;
    using postfx::softThreshold;
    const float t = 1.f, k = 0.5f;
    EXPECT_EQ(softThreshold(F4{0.5f, 0.2f, 0.1f, 1.f}, t, k)[0], 0.f);  // at threshold - knee
    // Above threshold + knee: colour x (br - T) / br exactly.
    const F4 out = softThreshold(F4{4.f, 2.f, 1.f, 1.f}, t, k);
    EXPECT_FLOAT_EQ(out[0], 3.f);
    EXPECT_FLOAT_EQ(out[1], 1.5f);
    EXPECT_FLOAT_EQ(out[3], 0.f);
    // The knee is continuous at both ends: (br - T + k)^2 / 4k meets br - T at br = T + k.
    const float justBelow = softThreshold(F4{1.4999f, 0, 0, 0}, t, k)[0],
                justAbove = softThreshold(F4{1.5001f, 0, 0, 0}, t, k)[0];
    EXPECT_NEAR(justBelow, justAbove, 1e-3f);
}

TEST(PostFxKernels, StreakChainsWeighEveryOffsetOnceByItsExponential) {
    // Convolving the passes of one chain must give weights proportional to a^n for n = 0..4^P-1.
    StreakParams sp;
    sp.length = 0.5f, sp.falloff = 3.f;
    const int width = 200;
    const auto plan = postfx::streakPasses(sp, width, 1.f);
    ASSERT_EQ(plan.right.size(), plan.left.size());
    std::vector<double> kernel{1.0};
    for (const auto& pass : plan.right) {
        std::vector<double> next(kernel.size() + std::size_t(3 * pass.step), 0.0);
        for (std::size_t i = 0; i < kernel.size(); ++i) {
            for (int k = 0; k < postfx::kStreakTaps; ++k)
                next[i + std::size_t(k * pass.step)] += kernel[i] * pass.weights[std::size_t(k)];
        }
        kernel = next;
    }
    const double a = std::exp(-3.0 / (0.5 * width));
    for (std::size_t n = 1; n < kernel.size(); ++n)
        EXPECT_NEAR(kernel[n] / kernel[n - 1], a, 1e-5) << n;
    EXPECT_GE(kernel.size(), std::size_t(0.5 * width));
}

TEST(PostFxGeometry, GhostsSitOnTheMirroredLineWhereTheScalePutsThem) {
    const int w = 512, h = 256;
    for (const auto& [lx, ly] :
         {std::pair{0.3, -0.2}, std::pair{-0.15, 0.25}, std::pair{0.2, 0.15}}) {
        const Image in =
            brightDot(w, h, float((lx + 1) / 2 * w), float((ly + 1) / 2 * h), 100.f, 3.f);
        for (float scale : {2.f, 1.f, 0.5f, -1.5f}) {
            auto r = runLayers(in, singleGhost(scale, 0.f, 1));
            ASSERT_TRUE(r.ok());
            const Moments m = moments(r->ghosts);
            ASSERT_GT(m.sum, 0.0);
            // A light at l appears at -l / scale; a tolerance of one working texel.
            EXPECT_NEAR(m.x, -lx / scale, 2.0 / r->ghosts.width())
                << "scale " << scale << " light " << lx << "," << ly;
            EXPECT_NEAR(m.y, -ly / scale, 2.0 / r->ghosts.height())
                << "scale " << scale << " light " << lx << "," << ly;
        }
    }
}

TEST(PostFxGeometry, Killzone2GhostsBlurAlongTheLineThroughTheCentre) {
    const int w = 640, h = 360;
    const double lx = 0.5, ly = -0.4;
    const Image in = brightDot(w, h, float((lx + 1) / 2 * w), float((ly + 1) / 2 * h), 200.f, 3.f);
    const PostFxParams kz = load("killzone2");
    for (std::size_t i = 0; i < kz.ghosts.size(); ++i) {
        PostFxParams p = kz;
        p.ghosts = {kz.ghosts[i]};
        p.bloom.intensity = 0.f;
        auto r = runLayers(in, p);
        ASSERT_TRUE(r.ok());
        const Moments m = moments(r->ghosts);
        const double s = kz.ghosts[i].scale;
        const double gx = -lx / s, gy = -ly / s;  // the unblurred ghost
        // The centroid lies on the line from the centre through the ghost (perpendicular
        // distance under two working texels)...
        const double len = std::hypot(gx, gy), ux = gx / len, uy = gy / len;
        EXPECT_LT(std::abs(m.x * uy - m.y * ux), 4.0 / r->ghosts.height()) << "ghost " << i;
        // ...and the seed's one-sided sample offsets (+1, -1, ..., -21 units, i.e. the samples
        // reach outward) smear the ghost toward the centre, by at most the sample span / scale.
        const GhostParams& g = kz.ghosts[i];
        const double span = (g.samples - 1) * 2.0 * g.blur * g.samples /
                            std::min(r->ghosts.width(), r->ghosts.height());
        const double along = m.x * ux + m.y * uy;
        EXPECT_LT(along, len) << "ghost " << i;
        EXPECT_GT(along, len - span / std::abs(s)) << "ghost " << i;
    }
}

TEST(PostFxGeometry, BlurStepsAreBloomTexelsSoTheyHalveInFrameUnitsAtTwiceTheSize) {
    // The seed divides its blur offset by g_vSourceDimensions: steps are texels of the bloom
    // buffer. The same scene at twice the resolution blurs half as far across the frame.
    double spread[2];
    for (int i = 0; i < 2; ++i) {
        const int w = 320 << i, h = 320 << i;
        // Light at l = (0.6, 0): 12 samples 2 x 1.2 bloom texels apart reach 0.33 (0.165) of the
        // frame inward, short of the centre, where the seed's blur direction flips.
        const Image in =
            brightDot(w, h, 0.8f * float(w), 0.5f * float(h), 200.f, 2.f * float(1 << i));
        auto r = runLayers(in, singleGhost(1.f, 0.1f, 12));
        ASSERT_TRUE(r.ok());
        const Moments m = moments(r->ghosts);
        spread[i] = spreadAlong(r->ghosts, m, 1.0, 0.0);  // the ghost's line is horizontal
    }
    // Not exactly 2: the blob itself (the same in frame units at both sizes) adds to the spread.
    EXPECT_GT(spread[0] / spread[1], 1.6);
    EXPECT_LT(spread[0] / spread[1], 2.05);
}

TEST(PostFxGeometry, NoLightNoFlare) {
    // Every value under threshold - knee: nothing passes the bright pass, the image is untouched.
    Image in = test::noiseImage(300, 170, 5);
    for (std::size_t i = 0; i < in.pixelCount() * 4; ++i) in.data()[i] *= 0.1f;  // [0, 0.4)
    for (const char* name : {"killzone2", "modern", "anamorphic", "subtle"}) {
        auto r = runLayers(in, load(name));
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(moments(r->lens).sum, 0.0) << name;
        for (std::size_t i = 0; i < in.pixelCount() * 4; ++i)
            ASSERT_EQ(r->final.data()[i], in.data()[i]) << name;
    }
}

TEST(PostFxGeometry, FlareEnergyIsLinearInTheLightAboveTheThreshold) {
    // Thresholds after the bright pass are clamps, not linear: set them to 0 and every later
    // pass (blur, ghosts, halo, streaks, chromatic, starburst, dirt) is linear in its input.
    for (const char* name : {"killzone2", "modern", "anamorphic", "subtle"}) {
        PostFxParams p = load(name);
        for (GhostParams& g : p.ghosts) g.threshold = 0.f;
        p.halo.threshold = p.streaks.threshold = 0.f;
        p.bright.ceiling = 0.f;  // highlight compression bends the curve on purpose
        p.bright.exposureRelative = false;
        const float t = p.bright.threshold, k = p.bright.knee;
        double perUnit[3];
        const float values[3] = {2.f * (t + k), 5.f * (t + k), 40.f * (t + k)};
        for (int i = 0; i < 3; ++i) {
            // A square light on whole 2x2 blocks, so every bright-pass pixel it touches is the
            // light's value and above the knee (edge pixels of a disc would be partial).
            Image light(400, 240);
            for (int y = 80; y < 96; ++y) {
                for (int x = 120; x < 136; ++x)
                    light.at(x, y) = {values[i], values[i], values[i], 1.f};
            }
            auto r = runLayers(light, p);
            ASSERT_TRUE(r.ok());
            perUnit[i] = moments(r->lens).sum / double(values[i] - t);
        }
        EXPECT_NEAR(perUnit[1] / perUnit[0], 1.0, 1e-4) << name;
        EXPECT_NEAR(perUnit[2] / perUnit[0], 1.0, 1e-4) << name;
    }
}

// With exposure_relative, the chain follows the frame's exposure: the same HDR frame two stops
// brighter gives exactly four times the flare (every threshold and the ceiling move with the
// frame's white, its metered luminance / 0.18), and the sun's flare is bounded by the ceiling.
TEST(PostFxExposure, AnExposureRelativeChainScalesWithTheFrame) {
    PostFxParams p = load("photo");
    ASSERT_TRUE(p.bright.exposureRelative);
    Image frame(320, 180);
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) {
            const float v = 0.05f + 0.3f * float(x) / 320.f;  // median about 0.2
            frame.at(x, y) = {v, v, v, 1.f};
        }
    for (int y = 40; y < 44; ++y)
        for (int x = 200; x < 204; ++x) frame.at(x, y) = {30000.f, 30000.f, 30000.f, 1.f};
    Image brighter = frame;
    for (std::size_t i = 0; i < brighter.pixelCount() * 4; ++i)
        if (i % 4 != 3) brighter.data()[i] *= 4.f;
    EXPECT_NEAR(frameWhite(brighter) / frameWhite(frame), 4.f, 1e-5f);
    EXPECT_NEAR(frameWhite(frame), 0.2f / 0.18f, 0.01f);
    auto a = runLayers(frame, p), b = runLayers(brighter, p);
    ASSERT_TRUE(a.ok() && b.ok());
    const double lensA = moments(a->lens).sum, lensB = moments(b->lens).sum;
    EXPECT_GT(lensA, 0.0);
    EXPECT_NEAR(lensB / lensA, 4.0, 4e-3);
    // 8-bit data (nothing above 1) is its own exposure.
    Image photo(64, 64);
    photo.fill({0.6f, 0.6f, 0.6f, 1.f});
    EXPECT_EQ(frameWhite(photo), 1.f);
    // One pixel past white between the metering samples (every 8th pixel here) still makes a
    // frame scene-referred, in any band of the scan; none leaves it display-referred.
    Image wide(1024, 512);
    wide.fill({0.5f, 0.5f, 0.5f, 1.f});
    EXPECT_EQ(frameWhite(wide), 1.f);
    for (const int y : {0, 300, 511}) {
        Image one = wide;
        one.at(1021, y).b = 1.01f;
        EXPECT_NEAR(frameWhite(one), 0.5f / 0.18f, 1e-4f) << y;
    }
}

TEST(PostFxExposure, TheCeilingBoundsWhatASunFeedsTheChain) {
    PostFxParams p = load("killzone2");
    p.bright.ceiling = 8.f;
    p.bright.areaReference = 0.f;  // the ceiling alone: on black, any sun is a wide light
    double lens[2];
    const float suns[2] = {1000.f, 100000.f};
    for (int i = 0; i < 2; ++i) {
        Image frame(320, 180);
        for (int y = 80; y < 84; ++y)
            for (int x = 100; x < 104; ++x) frame.at(x, y) = {suns[i], suns[i], suns[i], 1.f};
        auto r = runLayers(frame, p);
        ASSERT_TRUE(r.ok());
        lens[i] = moments(r->lens).sum;
    }
    // 8 tanh(1000 / 8) and 8 tanh(100000 / 8) are both 8: a hundred times the sun, one flare.
    EXPECT_NEAR(lens[1] / lens[0], 1.0, 1e-4);
    p.bright.ceiling = 0.f;
    Image frame(320, 180);
    for (int y = 80; y < 84; ++y)
        for (int x = 100; x < 104; ++x) frame.at(x, y) = {1000.f, 1000.f, 1000.f, 1.f};
    auto uncompressed = runLayers(frame, p);
    ASSERT_TRUE(uncompressed.ok());
    EXPECT_GT(moments(uncompressed->lens).sum, 50.0 * lens[0]);
}

TEST(PostFxEdgeCases, TheExactCentreOfAnOddBufferStaysFinite) {
    // 260 -> 130 -> 65: the working buffer is odd, so one pixel's mirrored coordinate is exactly
    // the centre, where the seed's normalize(-n) is a division by zero.
    const Image in = brightDot(260, 260, 130.f, 130.f, 100.f, 6.f);
    for (const char* name : {"killzone2", "modern"}) {
        auto r = runLayers(in, load(name));
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(r->ghosts.width(), 65);
        for (std::size_t i = 0; i < r->final.pixelCount() * 4; ++i)
            ASSERT_TRUE(std::isfinite(r->final.data()[i])) << name;
        // Here the blur has no direction: every sample lands on the point itself, so the pixel is
        // the unblurred ghost, no brighter than the bloom it reads.
        const Rgba c = r->ghosts.at(32, 32);
        EXPECT_GT(c.r, 0.f) << name;
        EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) << name;
    }
}

TEST(PostFxEdgeCases, NanAndInfInputPixelsDoNotSpread) {
    Image in = test::hdrSky(200, 120);
    in.at(20, 20).r = std::nanf("");
    in.at(150, 100).g = INFINITY;
    auto r = postFxCpu(in, load("modern"));
    ASSERT_TRUE(r.ok());
    std::size_t bad = 0;
    for (std::size_t i = 0; i < r->final.pixelCount() * 4; ++i)
        bad += !std::isfinite(r->final.data()[i]);
    EXPECT_EQ(bad, 2u);  // the two input values themselves, nothing else
}

TEST(PostFxEdgeCases, TinyImagesAndBadParams) {
    for (auto [w, h] : {std::pair{1, 1}, std::pair{3, 1}, std::pair{1, 7}, std::pair{5, 5}}) {
        auto r = postFxCpu(brightDot(w, h, 0.5f, 0.5f, 50.f, 1.f), load("modern"));
        ASSERT_TRUE(r.ok()) << w << "x" << h;
        EXPECT_EQ(r->final.width(), w);
    }
    EXPECT_FALSE(postFxCpu(Image(), load("modern")).ok());
    PostFxParams p = load("modern");
    p.ghosts[0].samples = 0;
    EXPECT_FALSE(postFxCpu(brightDot(8, 8, 4, 4, 9), p).ok());
    p = load("modern");
    p.bright.threshold = NAN;
    EXPECT_FALSE(postFxCpu(brightDot(8, 8, 4, 4, 9), p).ok());
}

TEST(PostFxEdgeCases, ToneCurvesMapIntoDisplayRangeAndKeepAlpha) {
    Image in = test::hdrSky(160, 90);
    in.at(3, 3).a = 0.25f;
    for (ToneOperator op : {ToneOperator::Aces, ToneOperator::Filmic}) {
        PostFxParams p = load("modern");
        p.tone.op = op;
        auto r = postFxCpu(in, p);
        ASSERT_TRUE(r.ok());
        float hi = 0;
        for (int y = 0; y < 90; ++y) {
            for (int x = 0; x < 160; ++x)
                hi = std::max({hi, r->final.at(x, y).r, r->final.at(x, y).g, r->final.at(x, y).b});
        }
        EXPECT_LE(hi, 1.f);
        EXPECT_GT(hi, 0.9f);  // the sun of 50 saturates
        EXPECT_EQ(r->final.at(3, 3).a, 0.25f);
    }
}

TEST(PostFxDirt, IsAPureFunctionOfItsParamsInZeroOne) {
    DirtParams d;
    d.spots = 50, d.seed = 11;
    const Image a = makeLensDirt(200, 100, d), b = makeLensDirt(200, 100, d);
    d.seed = 12;
    const Image c = makeLensDirt(200, 100, d);
    double sumA = 0, diff = 0;
    for (std::size_t i = 0; i < a.pixelCount() * 4; ++i) {
        ASSERT_EQ(a.data()[i], b.data()[i]);
        ASSERT_GE(a.data()[i], 0.f);
        ASSERT_LE(a.data()[i], 1.f);
        sumA += a.data()[i], diff += std::abs(a.data()[i] - c.data()[i]);
    }
    EXPECT_GT(sumA, 0.0);
    EXPECT_GT(diff, 0.0);
}

// The starburst radiates from the frame's bright source, not the frame centre: fitToFrame puts
// its centre on the light (in the passes' uv, y up), and along any ray from that centre the
// modulation is the same at every distance.
TEST(PostFxStarburst, RaysRadiateFromTheLight) {
    PostFxParams p = load("modern");
    ASSERT_GT(p.starburst.intensity, 0.f);
    ASSERT_EQ(p.starburst.centre, StarCentre::Lights);
    Image frame(320, 180);
    frame.fill({0.05f, 0.05f, 0.05f, 1.f});
    for (int y = 38; y < 42; ++y)
        for (int x = 238; x < 242; ++x) frame.at(x, y) = {5000.f, 5000.f, 5000.f, 1.f};
    const PostFxParams fitted = fitToFrame(p, frame);
    ASSERT_EQ(fitted.starburst.centreCount, 1);
    EXPECT_NEAR(fitted.starburst.centresUv[0], 240.f / 320.f, 1e-4f);
    EXPECT_NEAR(fitted.starburst.centresUv[1], 1.f - 40.f / 180.f, 1e-4f);
    const postfx::StarburstUniforms u = postfx::starburstUniforms(fitted.starburst);
    const float aspect = 320.f / 180.f;
    const postfx::Vec2 c{fitted.starburst.centresUv[0], fitted.starburst.centresUv[1]};
    for (float angle : {0.3f, 1.1f, 2.5f, 4.0f}) {
        auto at = [&](float r) {
            const postfx::Vec2 uv{c.x + r * std::cos(angle) / aspect, c.y + r * std::sin(angle)};
            return postfx::starburstModulation(u, uv, aspect);
        };
        EXPECT_NEAR(at(0.05f), at(0.4f), 1e-4f) << angle;
    }
    // "frame" keeps Chapman's centre.
    p.starburst.centre = StarCentre::Frame;
    const postfx::StarburstUniforms f = postfx::starburstUniforms(fitToFrame(p, frame).starburst);
    EXPECT_EQ(f.centres[0].x, 0.5f);
    EXPECT_EQ(f.centres[0].y, 0.5f);
}

}  // namespace
}  // namespace flarekit

namespace flarekit {

// The composite written over the input (what the CLI does for one CPU run) is the composite
// run() writes into its own buffer, bit for bit, layers included, for every shipped preset.
TEST(PostFxInPlace, TheCompositeOverTheInputIsRunsCompositeExactly) {
    for (const char* name : {"killzone2", "modern", "anamorphic", "subtle", "photo"}) {
        const PostFxParams p = load(name);
        const Image sky = test::hdrSky(320, 180);
        PostFxOptions options;
        options.keepLayers = true;
        PostFxResult separate, inPlace;
        ASSERT_TRUE(CpuPostFx().run(sky, p, separate, options).ok());
        Image image = sky;
        ASSERT_TRUE(CpuPostFx().runInPlace(image, p, inPlace, options).ok());
        EXPECT_TRUE(inPlace.final.empty()) << name;
        ASSERT_EQ(image.pixelCount(), separate.final.pixelCount());
        EXPECT_EQ(0, std::memcmp(image.data(), separate.final.data(),
                                 image.pixelCount() * 4 * sizeof(float)))
            << name;
        EXPECT_EQ(0, std::memcmp(inPlace.lens.data(), separate.lens.data(),
                                 separate.lens.pixelCount() * 4 * sizeof(float)))
            << name;
        EXPECT_GT(separate.lens.pixelCount(), 0u);
    }
}

}  // namespace flarekit

namespace flarekit {
namespace {

using postfx::F4;

//! A source of `w` x `h` with distinct, irregular values (and one negative, one huge lane), so
//! a wrong texel or weight anywhere shows.
Image irregular(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = {std::sin(0.37f * float(x) + 1.3f * float(y)) * 5.f,
                              float((x * 7919 + y * 104729) % 1000) * 0.013f,
                              (x == 1 && y == 0) ? 3.0e5f : 0.25f + 0.001f * float(x * y),
                              -0.5f + float(y)};
    return image;
}

bool sameBits(F4 a, F4 b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The separable walk is bilinear() bit for bit: upsampling by 4 (the composite's case), by odd
// and uneven ratios, to the same size, downsampling, from one-texel sources, at the clamped
// edges; rows visited by tasks starting anywhere.
TEST(BilinearRows, EveryValueIsBilinearsBitForBit) {
    const std::pair<std::pair<int, int>, std::pair<int, int>> cases[] = {
        {{480, 270}, {1920, 1080}}, {{33, 17}, {131, 67}}, {{5, 3}, {5, 3}}, {{64, 48}, {20, 13}},
        {{1, 1}, {9, 7}},           {{1, 6}, {11, 19}},    {{7, 1}, {3, 5}},
    };
    for (const auto& [src, dst] : cases) {
        const Image source = irregular(src.first, src.second);
        const postfx::Tex tex(source);
        const postfx::Vec2 inv = postfx::inverseSize(dst.first, dst.second);
        const postfx::BilinearColumns columns(tex, dst.first, inv);
        for (int start : {0, dst.second / 3, dst.second - 1}) {
            postfx::BilinearRows rows(columns);
            int mismatches = 0;
            for (int y = start; y < dst.second; ++y) {
                const postfx::BilinearRows::Pair p = rows.at(y);
                for (int x = 0; x < dst.first; ++x) {
                    const F4 separable = p.top[x] + (p.bottom[x] - p.top[x]) * p.fy;
                    mismatches +=
                        !sameBits(separable, postfx::bilinear(tex, postfx::pixelUv(x, y, inv)));
                }
            }
            EXPECT_EQ(mismatches, 0) << src.first << "x" << src.second << " -> " << dst.first << "x"
                                     << dst.second << " from row " << start;
        }
    }
}

// The composite's row draw writes what its per-pixel kernel (composite.frag's twin) writes, bit
// for bit, with and without a display curve, over a separate output and in place.
TEST(BilinearRows, TheCompositesRowDrawIsItsPixelKernel) {
    for (int op : {int(ToneOperator::None), int(ToneOperator::Aces), int(ToneOperator::Filmic)}) {
        for (auto [w, h] : {std::pair{1920, 1080}, std::pair{321, 181}, std::pair{2, 1}}) {
            const Image input = irregular(w, h);
            const Image lens = irregular(postfx::halfSize(postfx::halfSize(w)),
                                         postfx::halfSize(postfx::halfSize(h)));
            const postfx::CompositeUniforms u{postfx::inverseSize(w, h), op, 1.7f};
            const postfx::Tex in[2] = {postfx::Tex(input), postfx::Tex(lens)};
            Image expected(w, h), drawn(w, h);
            postfx::runPass(expected, [&](int x, int y) { return postfx::passPixel(u, in, x, y); });
            postfx::drawPass(u, in, drawn);
            EXPECT_EQ(0, std::memcmp(expected.data(), drawn.data(),
                                     expected.pixelCount() * 4 * sizeof(float)))
                << w << "x" << h << " tone " << op;
            Image inPlace = input;
            const postfx::Tex over[2] = {postfx::Tex(inPlace), postfx::Tex(lens)};
            postfx::drawPass(u, over, inPlace);
            EXPECT_EQ(0, std::memcmp(expected.data(), inPlace.data(),
                                     expected.pixelCount() * 4 * sizeof(float)))
                << w << "x" << h << " tone " << op << " in place";
        }
    }
}

}  // namespace
}  // namespace flarekit
