// SPDX-License-Identifier: Apache-2.0
// Golden images of the CPU paths: every shipped sprite preset (the `apply` path: light found,
// flare added in linear light) and every shipped postfx preset on the sample sunset, at
// 320x180. Both paths are deterministic float code, so the tolerance is one 8-bit level
// (rounding at an encode boundary) with a mean far below one.
#include "GoldenImage.h"

#include <algorithm>
#include <cmath>

#include "flarekit/Flare.h"
#include "flarekit/Lens.h"
#include "flarekit/PostFx.h"
#include "flarekit/Tonemap.h"

using namespace flarekit;

namespace {

//! The golden input: the HDR sample sunset at 320x180, shipped as tests/golden/input/
//! sunset-hdr-320x180.exr (made once with `oiiotool samples/sunset-hdr.exr --resize 320x180`),
//! so no library code sits between the file and the path under test.
const Image& sunset() {
    static const Image image = [] {
        auto loaded = readImage(std::string(FLAREKIT_GOLDEN_INPUT) + "/sunset-hdr-320x180.exr");
        return loaded ? loaded->image : Image(320, 180);
    }();
    return image;
}

}  // namespace

TEST(Golden, EverySpritePresetOnTheHdrSunset) {
    ASSERT_GT(sunset().at(0, 0).r + sunset().at(160, 60).r, 0.f)
        << "samples/sunset-hdr.exr did not load";
    const std::vector<std::string> names = shippedPresetNames();
    ASSERT_GE(names.size(), 6u);
    for (const std::string& name : names) {
        auto preset = loadPreset(name);
        ASSERT_TRUE(preset.ok()) << name;
        Image image = sunset();
        const LightSearch search = findLights(image);
        ASSERT_EQ(search.lights.size(), 1u) << name << ": " << search.whyNone;
        flareLights(image, *preset, search);
        tonemapAcesFitted(image,
                          1.f);  // HDR to display range so the 8-bit reference keeps the flare
        golden::expectMatches("sprite-" + name, image);
    }
}

TEST(Golden, EveryLensOnTheRealSunrise) {
    // `lens render` on the blender-data sunrise: the light found as --light auto finds it, the
    // brightest 32 ghosts at the command's default gain of 100, RGB, composite, ACES.
    auto loaded = readImage(std::string(FLAREKIT_GOLDEN_INPUT) + "/sunrise-blender-320x180.exr");
    ASSERT_TRUE(loaded.ok());
    const Image& input = loaded->image;
    const auto lights = brightSources(input, 2.0, int(std::hypot(320.0, 180.0)) / 16, 1);
    ASSERT_EQ(lights.size(), 1u);
    const std::vector<std::string> names = lensNames();
    ASSERT_GE(names.size(), 5u);
    for (const std::string& name : names) {
        auto lens = loadLens(name);
        ASSERT_TRUE(lens.ok()) << name;
        LensRenderOptions o;
        o.ghosts = 32;
        auto layers = renderLensFlare(*lens, 320, 180, lights, o);
        ASSERT_TRUE(layers.ok()) << name << ": " << layers.error().message;
        Image image = input;
        for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) {
            if (i % 4 != 3)
                image.data()[i] += layers->ghosts.data()[i] + layers->starburst.data()[i] +
                                   layers->glare.data()[i];
        }
        tonemapAcesFitted(image, 1.f);
        golden::expectMatches("lens-" + name, image);
    }
}

TEST(Golden, EveryPostFxPresetOnTheHdrSunset) {
    const std::vector<std::string> names = shippedPostFxPresetNames();
    ASSERT_GE(names.size(), 4u);
    for (const std::string& name : names) {
        auto params = loadPostFxPreset(name);
        ASSERT_TRUE(params.ok()) << name;
        params->tone.op = ToneOperator::Aces;
        auto result = postFxCpu(sunset(), *params);
        ASSERT_TRUE(result.ok()) << name << ": " << result.error().message;
        golden::expectMatches("postfx-" + name, result->final);
    }
}

namespace {

//! Real material: a 320x180 crop of the CC0 "sunrise" HDR environment photograph of Debian's
//! blender-data package (studiolights/world/sunrise.exr, its 640x360 region at 194,113 with the
//! sun at 31,000, box-filtered down by oiiotool).
const Image& realSunrise() {
    static const Image image = [] {
        auto loaded =
            readImage(std::string(FLAREKIT_GOLDEN_INPUT) + "/sunrise-blender-320x180.exr");
        return loaded ? loaded->image : Image(320, 180);
    }();
    return image;
}

//! sRGB code of a linear value clipped to [0, 1]: the plain "clipped sRGB view" of an EXR.
int clippedSrgb(float v) {
    v = std::clamp(v, 0.f, 1.f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
    return int(std::lround(s * 255.f));
}

struct ViewChange {
    double newlyClipped = 0;  //!< share of pixels with a channel newly at or above 1
    double changed30 = 0;     //!< share of pixels whose clipped sRGB view moved > 30 levels
};
ViewChange viewChange(const Image& before, const Image& after) {
    ViewChange c;
    for (std::size_t i = 0; i < before.pixelCount(); ++i) {
        const float *a = before.data() + 4 * i, *b = after.data() + 4 * i;
        bool wasClipped = false, isClipped = false;
        int step = 0;
        for (int k = 0; k < 3; ++k) {
            wasClipped |= a[k] >= 1.f;
            isClipped |= b[k] >= 1.f;
            step = std::max(step, std::abs(clippedSrgb(b[k]) - clippedSrgb(a[k])));
        }
        c.newlyClipped += isClipped && !wasClipped;
        c.changed30 += step > 30;
    }
    c.newlyClipped /= double(before.pixelCount());
    c.changed30 /= double(before.pixelCount());
    return c;
}

}  // namespace

// On a real HDR sun the defaults give a strong but contained flare: `apply`'s (the default
// sprite preset, its light found and scaled by its flux) newly clips at most 2% of the frame,
// the default postfx preset changes less than 15% of it by more than 30 levels, both in a plain
// clipped sRGB view of the linear result; and the pictures are held as goldens.
TEST(Golden, DefaultsOnARealHdrSunAreStrongButContained) {
    ASSERT_GT(realSunrise().at(0, 0).b, 0.f) << "the real sunrise crop did not load";
    Image sprite = realSunrise();
    const LightSearch search = findLights(sprite);
    ASSERT_EQ(search.lights.size(), 1u) << search.whyNone;
    EXPECT_NEAR(search.lights[0].position.x, 210.f, 2.f);  // the sun, at 420,120 in the crop
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    flareLights(sprite, *preset, search);
    const ViewChange a = viewChange(realSunrise(), sprite);
    EXPECT_LE(a.newlyClipped, 0.02);
    EXPECT_GT(a.changed30, 0.005);  // and there is a flare to see

    auto params = loadPostFxPreset("photo");
    ASSERT_TRUE(params.ok());
    auto post = postFxCpu(realSunrise(), *params);
    ASSERT_TRUE(post.ok()) << post.error().message;
    const ViewChange b = viewChange(realSunrise(), post->final);
    EXPECT_LT(b.changed30, 0.15);
    EXPECT_GT(b.changed30, 0.01);

    toneMapImage(sprite, ToneOperator::Filmic, 1.f);
    golden::expectMatches("real-sunrise-apply", sprite);
    Image filmic = post->final;
    toneMapImage(filmic, ToneOperator::Filmic, 1.f);
    golden::expectMatches("real-sunrise-postfx", filmic);
}
