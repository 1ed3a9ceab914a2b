// SPDX-License-Identifier: Apache-2.0
// Uploads and read-backs through pixel buffers (gl/PixelTransfer.h): every value arrives, in
// bands (a frame larger than one band buffer), as floats and as halves; and the post-process
// chain gives the same result whichever way its image travels. Runs on llvmpipe in CI.
#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "GlTestContext.h"
#include "PostFxImages.h"
#include "core/HalfFloat.h"
#include "flarekit/PostFx.h"
#include "gl/GlObjects.h"
#include "gl/PixelTransfer.h"

using namespace flarekit;

namespace {

//! Random HDR values, rounded to halves when `halves` (what a half EXR holds).
Image randomImage(int w, int h, bool halves) {
    std::mt19937 rng(unsigned(w * 7 + h));
    std::uniform_real_distribution<float> value(-2.f, 60.f);
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) {
        const float v = value(rng);
        image.data()[i] = halves ? float(half(v)) : v;
    }
    return image;
}

}  // namespace

TEST(PixelTransfer, FramesLargerThanABandArriveExactlyAsFloatsAndHalves) {
    test::glContext();
    // 1031 x 1100 floats are 18 MB: three 8 MiB bands, the last one short.
    for (bool halves : {false, true}) {
        const Image image = randomImage(1031, 1100, halves);
        gl::Texture texture =
            gl::makeTexture2D(halves ? GL_RGBA16F : GL_RGBA32F, image.width(), image.height());
        gl::PixelTransfer transfer;
        ASSERT_TRUE(transfer.upload(texture.get(), image, halves).ok());
        for (bool halfBack : {false, true}) {
            Image back;
            ASSERT_TRUE(
                transfer.download(texture.get(), image.width(), image.height(), halfBack, back)
                    .ok());
            ASSERT_EQ(back.width(), image.width());
            // Read back as halves, a float texture's values come rounded to half.
            for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) {
                const float v = image.data()[i];
                ASSERT_EQ(back.data()[i], halfBack ? float(half(v)) : v)
                    << halves << halfBack << " " << i;
            }
        }
    }
}

TEST(PixelTransfer, TheChainGivesTheSameResultWhicheverWayItsImageTravels) {
    test::glContext();
    auto chain = GpuPostFx::create();
    ASSERT_TRUE(chain.ok()) << chain.error().message;
    const Image sky = test::hdrSky(384, 216);
    Image input(sky.width(), sky.height());
    for (std::size_t i = 0; i < sky.pixelCount() * 4; ++i)
        input.data()[i] = float(half(sky.data()[i]));
    const PostFxParams params;
    auto floats = chain->run(input, params, {});
    ASSERT_TRUE(floats.ok());
    PostFxOptions halves;
    halves.halfInput = true;
    halves.halfReadback = true;
    auto viaHalves = chain->run(input, params, halves);
    ASSERT_TRUE(viaHalves.ok());
    // A half input texture holds the same values; a half read-back is the float result
    // rounded to half, as the half EXR writer would round it.
    for (std::size_t i = 0; i < input.pixelCount() * 4; ++i) {
        ASSERT_EQ(viaHalves->final.data()[i], float(half(floats->final.data()[i]))) << i;
    }
    // And back to floats: the source texture is made again at full precision.
    auto again = chain->run(input, params, {});
    ASSERT_TRUE(again.ok());
    for (std::size_t i = 0; i < input.pixelCount() * 4; ++i)
        ASSERT_EQ(again->final.data()[i], floats->final.data()[i]) << i;
}

TEST(PixelTransfer, EveryPassAndTransferIsTimedWithinItsWallTime) {
    // The timer queries bracket each group with two timestamps: a GPU figure is never negative
    // and never more than the wall time around it (a first draw once read as hours).
    test::glContext();
    auto chain = GpuPostFx::create();
    ASSERT_TRUE(chain.ok()) << chain.error().message;
    std::vector<PassTime> times;
    PostFxOptions options;
    options.times = &times;
    for (int run = 0; run < 2; ++run)
        ASSERT_TRUE(chain->run(test::hdrSky(384, 216), {}, options).ok());
    ASSERT_GE(times.size(), 4u);
    EXPECT_EQ(times.front().pass, "upload");
    EXPECT_EQ(times.back().pass, "read-back");
    for (const PassTime& t : times) {
        EXPECT_GE(t.milliseconds, 0.0) << t.pass;
        EXPECT_LE(t.milliseconds, t.wallMilliseconds + 0.5) << t.pass;
        EXPECT_GT(t.wallMilliseconds, 0.0) << t.pass;
    }
}
