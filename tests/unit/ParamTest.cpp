// SPDX-License-Identifier: Apache-2.0
// The one parameter description (flarekit/Param.h): JSON input and parameters built in code
// go through the same check, with the same field names and ranges.
#include <gtest/gtest.h>

#include <cmath>

#include "flarekit/Demo.h"
#include "flarekit/Flare.h"
#include "flarekit/ParamText.h"
#include "flarekit/PostFx.h"
#include "flarekit/Scene.h"
#include "flarekit/Temporal.h"
#include "flarekit/Visibility.h"

using namespace flarekit;

namespace {

//! {"section": {"key": value}} as preset text.
std::string sectionJson(std::string_view section, std::string_view key, const std::string& value) {
    return "{\"" + std::string(section) + "\": {\"" + std::string(key) + "\": " + value + "}}";
}

//! Sets one parameter of the owner to `x` (numbers) through its description.
template <class Owner>
void setNumber(const Param<Owner>& p, Owner& owner, double x) {
    ParamValue v = p.get(owner);
    v.number = x;
    v.color = {float(x), float(x), float(x)};
    p.set(owner, v);
}

//! For every numeric or colour parameter of a postfx section: a value past the range is refused
//! by the JSON reader and by validatePostFxParams (params built in code) naming the same field,
//! and the range's ends are accepted by both.
template <class Owner>
void checkSection(std::string_view section, std::span<const Param<Owner>> table,
                  Owner PostFxParams::*member) {
    for (const Param<Owner>& p : table) {
        if (p.type == ParamType::Bool || p.type == ParamType::Choice) continue;
        const std::string field = std::string(section) + "." + std::string(p.key);
        const double tooBig =
            p.max + (p.type == ParamType::Number || p.type == ParamType::Color ? 0.5 : 1);
        const std::string text = p.type == ParamType::Color
                                     ? "[" + std::to_string(tooBig) + ", 0, 0]"
                                     : std::to_string(tooBig);
        auto parsed = parsePostFxPreset(sectionJson(section, p.key, text), "p.json");
        ASSERT_FALSE(parsed.ok()) << field;
        EXPECT_NE(parsed.error().message.find("p.json: " + field + ": expected " + expectedText(p)),
                  std::string::npos)
            << parsed.error().message;

        PostFxParams code;
        setNumber(p, code.*member, tooBig);
        const Status s = validatePostFxParams(code);
        ASSERT_FALSE(s.ok()) << field;
        EXPECT_EQ(s.error().message.rfind(field + ": expected " + expectedText(p), 0), 0u)
            << s.error().message;
        auto planned = postFxCpu(Image(8, 8), code);
        ASSERT_FALSE(planned.ok()) << field;
        EXPECT_NE(planned.error().message.find(field), std::string::npos)
            << planned.error().message;

        for (double end : {p.min, p.max}) {
            PostFxParams ok;
            setNumber(p, ok.*member, end);
            EXPECT_TRUE(validatePostFxParams(ok).ok()) << field << " = " << end;
            const std::string endText = p.type == ParamType::Color
                                            ? "[" + formatParamNumber(end) + ", 0, 0]"
                                            : formatParamNumber(end);
            auto fromJson = parsePostFxPreset(sectionJson(section, p.key, endText), "p.json");
            EXPECT_TRUE(fromJson.ok()) << field << " = " << endText << ": "
                                       << (fromJson.ok() ? "" : fromJson.error().message);
        }
    }
}

}  // namespace

TEST(Params, JsonAndCodeBuiltPostFxParamsGoThroughOneValidator) {
    checkSection<BrightParams>("bright", kBrightParams, &PostFxParams::bright);
    checkSection<BloomParams>("bloom", kBloomParams, &PostFxParams::bloom);
    checkSection<HaloParams>("halo", kHaloParams, &PostFxParams::halo);
    checkSection<StreakParams>("streaks", kStreakParams, &PostFxParams::streaks);
    checkSection<ChromaticParams>("chromatic", kChromaticParams, &PostFxParams::chromatic);
    checkSection<StarburstParams>("starburst", kStarburstParams, &PostFxParams::starburst);
    checkSection<DirtParams>("dirt", kDirtParams, &PostFxParams::dirt);
    checkSection<ToneParams>("tonemap", kToneParams, &PostFxParams::tone);
}

TEST(Params, StarburstWidthHasOneRange) {
    // The chain used to accept any width > 0 while presets required [0.01, 1].
    PostFxParams p;
    p.starburst.width = 0.005f;
    const Status s = validatePostFxParams(p);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, "starburst.width: expected a number in [0.01, 1], got 0.005");
    EXPECT_FALSE(parsePostFxPreset(R"({"starburst": {"width": 0.005}})", "p.json").ok());
}

TEST(Params, CodeBuiltGhostsAreCheckedLikeJsonOnes) {
    PostFxParams p;
    p.ghosts.resize(2);
    p.ghosts[1].samples = 65;
    EXPECT_EQ(validatePostFxParams(p).error().message,
              "ghosts[1].samples: expected an integer in [1, 64], got 65");
    p.ghosts[1].samples = 12;
    p.ghosts[1].scale = 0.01f;
    EXPECT_EQ(validatePostFxParams(p).error().message.rfind(
                  "ghosts[1].scale: expected |scale| >= 0.05", 0),
              0u);
    p.ghosts.assign(std::size_t(kMaxGhosts) + 1, GhostParams{});
    EXPECT_NE(validatePostFxParams(p).error().message.find("at most 32 ghosts"), std::string::npos);
    p.ghosts.clear();
    p.flareIntensity = std::nanf("");
    EXPECT_EQ(validatePostFxParams(p).error().message.rfind(
                  "flare_intensity: expected a number in [0, 1000]", 0),
              0u);
}

TEST(Params, EveryPostFxDefaultIsInsideItsOwnRange) {
    EXPECT_TRUE(validatePostFxParams(PostFxParams{}).ok());
    EXPECT_TRUE(validateTemporalParams(TemporalParams{}).ok());
    DemoSettings demo;
    EXPECT_TRUE(validateDemoSettings(demo).ok());
    for (int t = 0; t < kElementTypeCount; ++t) {
        Preset preset;
        preset.elements.push_back(defaultElement(ElementType(t)));
        // An image element's texture is part of it, not a default.
        if (ElementType(t) == ElementType::Image)
            preset.elements.back().textureImage = std::make_shared<const Image>(2, 2);
        EXPECT_TRUE(validatePreset(preset).ok()) << t;
    }
}

TEST(Params, CodeBuiltPresetsAreCheckedLikeJsonOnes) {
    Preset preset;
    preset.elements.push_back(defaultElement(ElementType::Ring));
    preset.elements.push_back(defaultElement(ElementType::Glow));
    preset.elements[1].size = 5;
    EXPECT_EQ(validatePreset(preset).error().message,
              "element[1].size: expected a number in [0, 4], got 5");
    // A field that does not apply to the type is not checked (a glow has no blades).
    preset.elements[1].size = 0.2f;
    preset.elements[1].blades = 0;
    EXPECT_TRUE(validatePreset(preset).ok());
    preset.elements[0].width = 0;
    EXPECT_EQ(validatePreset(preset).error().message,
              "element[0].width: expected a number in [0.001, 1], got 0");
    auto fromJson = parsePreset(R"({"elements": [{"type": "ring", "width": 0}]})", "r.json");
    ASSERT_FALSE(fromJson.ok());
    EXPECT_EQ(fromJson.error().message,
              "r.json: element[0].width: expected a number in [0.001, 1], got 0");
}

TEST(Params, TemporalAndDemoSettingsNameTheirField) {
    TemporalParams t;
    t.guardBand = 2;
    EXPECT_EQ(validateTemporalParams(t).error().message,
              "guard-band: expected a number in [0, 0.5], got 2");
    DemoSettings d;
    d.frames = 0;
    EXPECT_EQ(validateDemoSettings(d).error().message,
              "frames: expected an integer in [1, 100000], got 0");
    d.frames = 10;
    d.msaaSamples = 3;
    EXPECT_EQ(validateDemoSettings(d).error().message, "msaa: expected one of 1, 2, 4, 8, got 3");
}

TEST(Params, ChoicesReadByNameAndPrintedAsTheDocsShowThem) {
    const Param<ToneParams>& op = *findParam<ToneParams>(kToneParams, "operator");
    EXPECT_EQ(expectedText(op), R"(one of "none", "aces", "filmic")");
    EXPECT_EQ(rangeText(op), "`none`, `aces`, `filmic`");
    ToneParams tone;
    op.set(tone, ParamValue{2, {}, true});
    EXPECT_EQ(tone.op, ToneOperator::Filmic);
    EXPECT_EQ(valueText(op, op.get(tone)), "`filmic`");
    const Param<StarburstParams>& seed = *findParam<StarburstParams>(kStarburstParams, "seed");
    EXPECT_EQ(rangeText(seed), "[0, 2147483647]");
}

TEST(Params, SceneJsonReadsThroughTheSameTables) {
    const auto error = [](const std::string& objectsAndMore) {
        const std::string text =
            R"({"image": {"width": 64, "height": 32}, "camera": {"position": [0,0,0], )"
            R"("look_at": [0,0,-1]}, "sun": {"direction": [0,0,-1]}, )" +
            objectsAndMore + "}";
        auto r = parseScene(text, "s.json");
        return r.ok() ? std::string("(ok)") : r.error().message;
    };
    EXPECT_EQ(error(R"("objects": [{"type": "sphere", "radius": 1}])"),
              "s.json: objects[0].center: missing; expected an array of 3 numbers");
    EXPECT_EQ(error(R"("objects": [{"type": "sphere", "center": [0,0,-5], "radius": 0}])"),
              "s.json: objects[0].radius: expected a positive number, got 0");
    EXPECT_EQ(
        error(R"("objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "color": [1,-1,0]}])"),
        "s.json: objects[0].color: expected an array of 3 non-negative numbers, got [1,-1,0]");
    EXPECT_EQ(
        error(R"("objects": [{"type": "triangles", "vertices": [[0,0,0],[1,0,0],[0,"x",0]]}])"),
        R"(s.json: objects[0].vertices[2]: expected an array of 3 numbers, got [0,"x",0])");
    EXPECT_EQ(error(R"("objects": [], "light": [])"),
              "s.json: light: unknown key (expected one of: image, camera, sun, lights, ground, "
              "objects)");
    const Param<SceneCamera>& fov = *findParam<SceneCamera>(kSceneCameraParams, "fov_y_deg");
    EXPECT_EQ(expectedText(fov), "a number in (0, 179]");
    SceneCamera camera;
    camera.fovYDeg = 0;
    EXPECT_EQ(validateParams<SceneCamera>(camera, kSceneCameraParams, "camera.").error().message,
              "camera.fov_y_deg: expected a number in (0, 179], got 0");
    auto ok = parseScene(
        R"({"image": {"width": 64, "height": 32}, "camera": {"position": [0,0,0], "look_at": [0,0,-1],
        "fov_y_deg": 179}, "sun": {"direction": [0,0,-2], "intensity": 0},
        "objects": [{"type": "triangles", "vertices": [[0,0,-1],[1,0,-1],[0,1,-1]], "color": [0,0,0]}]})",
        "s.json");
    ASSERT_TRUE(ok.ok()) << ok.error().message;
    EXPECT_DOUBLE_EQ(ok->sun.direction.z, -1.0);  // normalised on load
    EXPECT_EQ(ok->triangles.size(), 1u);
}

TEST(Params, ScenesBuiltInCodeAreCheckedLikeJsonOnes) {
    Scene s;
    EXPECT_TRUE(validateScene(s).ok());
    s.spheres.push_back({{0, 0, -5}, 0, {1, 1, 1}});
    auto r = raycastVisibility(s);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "scene: spheres[0].radius: expected a positive number, got 0");
    s.spheres[0].radius = 1;
    s.sun.direction = {0, 0, 0};
    EXPECT_EQ(validateScene(s).error().message, "sun.direction: expected a non-zero direction");
    s.sun.direction = {0, 0, -1};
    s.camera.fovYDeg = 180;
    EXPECT_EQ(validateScene(s).error().message,
              "camera.fov_y_deg: expected a number in (0, 179], got 180");
    s.camera.fovYDeg = 60;
    s.boxes.push_back({{0, 0, 0}, {1, 0, 1}, {0.5, 0.5, 0.5}});
    EXPECT_EQ(validateScene(s).error().message,
              "boxes[0].max: expected every component greater than min's");
}
