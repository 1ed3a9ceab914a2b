// Golden images of the CPU paths: every shipped sprite preset (the `apply` path: light found,
// flare added in linear light) and every shipped postfx preset on the sample sunset, at
// 320x180. Both paths are deterministic float code, so the tolerance is one 8-bit level
// (rounding at an encode boundary) with a mean far below one.
#include "GoldenImage.h"

#include "flarekit/Flare.h"
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
