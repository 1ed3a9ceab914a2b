// SPDX-License-Identifier: Apache-2.0
// CPU vs OpenGL post-process chains: for every shipped preset on every test image,
// float results within 1e-3 relative (with a floor of 1e-3 absolute for values near zero,
// where "relative" means nothing), and 8-bit sRGB encodings at most 1 level apart. Runs on
// Mesa llvmpipe in CI; never skipped.
#include <gtest/gtest.h>

#include <cmath>

#include "GlTestContext.h"
#include "PostFxImages.h"
#include "flarekit/Color.h"
#include "flarekit/PostFx.h"

namespace flarekit {
namespace {

struct Diff {
    double worstRelative = 0;  //!< max |a - b| / max(|a|, |b|, floor)
    int worst8Bit = 0;         //!< max 8-bit level difference
    int x = 0, y = 0, c = 0;   //!< where worstRelative is
};

constexpr double kRelative = 1e-3;
constexpr double kFloor = 1e-3;  //!< values below this compare absolutely

Diff compare(const Image& cpu, const Image& gpu) {
    Diff d;
    for (int y = 0; y < cpu.height(); ++y) {
        const float* a = cpu.row(y);
        const float* b = gpu.row(y);
        for (int i = 0; i < cpu.width() * 4; ++i) {
            const double rel = std::abs(double(a[i]) - b[i]) /
                               std::max({std::abs(double(a[i])), std::abs(double(b[i])), kFloor});
            if (rel > d.worstRelative) d.worstRelative = rel, d.x = i / 4, d.y = y, d.c = i % 4;
            if (i % 4 != 3) {
                const int levels = std::abs(int(linearToSrgb8(a[i])) - int(linearToSrgb8(b[i])));
                d.worst8Bit = std::max(d.worst8Bit, levels);
            }
        }
    }
    return d;
}

struct TestImage {
    const char* name;
    Image image;
};

//! A sun of 50,000 on a 0.2 plate with a resize's negative ringing (-3,600) around it and the
//! largest half beside it: the bright pass reads light, never negative, on both chains.
Image ringingSun(int w, int h) {
    Image image = test::brightDot(w, h, 60.5f, 40.5f, 50000.f, 3.f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = std::hypot(float(x) + 0.5f - 60.5f, float(y) + 0.5f - 40.5f);
            Rgba& p = image.at(x, y);
            if (d >= 3.f && d < 4.5f) p = {-3600.f, -3600.f, -3600.f, 1.f};
            if (d >= 4.5f) p = {0.2f, 0.2f, 0.2f, 1.f};
        }
    image.at(150, 20) = {65504.f, -1000.f, 1e-41f, 1.f};
    return image;
}

std::vector<TestImage> testImages() {
    // Odd sizes on purpose: rounding-up of every chain level and an exact-centre pixel.
    return {
        {"bright dot", test::brightDot(321, 181, 230.f, 60.f, 60.f, 3.f)},
        {"several lights", test::severalLights(400, 224)},
        {"HDR sky, sun 50", test::hdrSky(384, 216)},
        {"noise", test::noiseImage(203, 117, 9)},
        {"sun 50000 with negative ringing", ringingSun(197, 111)},
    };
}

TEST(PostFxParity, EveryPresetOnEveryImageCpuMatchesGl) {
    test::glContext();
    auto gpu = GpuPostFx::create();
    ASSERT_TRUE(gpu.ok()) << gpu.error().message;
    double worst = 0;
    int worst8 = 0;
    for (const std::string preset : {"killzone2", "modern", "anamorphic", "subtle", "photo"}) {
        auto params = loadPostFxPreset(preset);
        ASSERT_TRUE(params.ok()) << params.error().message;
        for (ToneOperator op : {ToneOperator::None, ToneOperator::Aces}) {
            params->tone.op = op;
            for (const TestImage& t : testImages()) {
                auto cpu = postFxCpu(t.image, *params);
                auto gl = gpu->run(t.image, *params);
                ASSERT_TRUE(cpu.ok() && gl.ok());
                const Diff d = compare(cpu->final, gl->final);
                const std::string where =
                    preset + (op == ToneOperator::Aces ? " +aces" : "") + ", " + t.name;
                EXPECT_LE(d.worstRelative, kRelative)
                    << where << " at " << d.x << "," << d.y << " channel " << d.c << ": cpu "
                    << cpu->final.row(d.y)[d.x * 4 + d.c] << " gl "
                    << gl->final.row(d.y)[d.x * 4 + d.c];
                EXPECT_LE(d.worst8Bit, 1) << where;
                worst = std::max(worst, d.worstRelative), worst8 = std::max(worst8, d.worst8Bit);
            }
        }
    }
    std::printf("worst relative difference %.3g, worst 8-bit difference %d level(s)\n", worst,
                worst8);
}

TEST(PostFxParity, LayersMatchToo) {
    test::glContext();
    auto gpu = GpuPostFx::create();
    ASSERT_TRUE(gpu.ok());
    auto params = loadPostFxPreset("modern");
    ASSERT_TRUE(params.ok());
    params->streaks.intensity = 1.f;  // every layer on
    PostFxOptions o;
    o.keepLayers = true;
    const Image in = test::hdrSky(300, 170);
    auto cpu = postFxCpu(in, *params, o);
    auto gl = gpu->run(in, *params, o);
    ASSERT_TRUE(cpu.ok() && gl.ok());
    for (auto [name, a, b] : {std::tuple{"bloom", &cpu->bloom, &gl->bloom},
                              std::tuple{"ghosts", &cpu->ghosts, &gl->ghosts},
                              std::tuple{"halo", &cpu->halo, &gl->halo},
                              std::tuple{"streaks", &cpu->streaks, &gl->streaks},
                              std::tuple{"lens", &cpu->lens, &gl->lens}}) {
        ASSERT_EQ(a->width(), b->width()) << name;
        double energy = 0;
        for (std::size_t i = 0; i < a->pixelCount() * 4; ++i) energy += a->data()[i];
        EXPECT_GT(energy, 0.0) << name << " is empty: the comparison would prove nothing";
        EXPECT_LE(compare(*a, *b).worstRelative, kRelative) << name;
    }
}

TEST(PostFxParity, GpuChainReusesItsTargetsAcrossSizes) {
    test::glContext();
    auto gpu = GpuPostFx::create();
    ASSERT_TRUE(gpu.ok());
    auto params = loadPostFxPreset("killzone2");
    ASSERT_TRUE(params.ok());
    for (auto [w, h] : {std::pair{64, 48}, std::pair{1, 1}, std::pair{97, 13}, std::pair{64, 48}}) {
        const Image in = test::brightDot(w, h, float(w) * 0.3f, float(h) * 0.6f, 30.f, 2.f);
        auto cpu = postFxCpu(in, *params);
        auto gl = gpu->run(in, *params);
        ASSERT_TRUE(cpu.ok() && gl.ok()) << w << "x" << h;
        EXPECT_LE(compare(cpu->final, gl->final).worstRelative, kRelative) << w << "x" << h;
    }
}

}  // namespace
}  // namespace flarekit
