// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include "flarekit/Flare.h"

using namespace flarekit;

namespace {
std::string errorOf(const std::string& json) {
    auto r = parsePreset(json, "my.json");
    if (r.ok()) return "(ok)";
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << "one line";
    return r.error().message;
}
const std::string kThree = R"({"type":"glow"},{"type":"ring"},{"type":"disc"},)";
}  // namespace

TEST(Preset, EveryShippedPresetLoads) {
    const auto names = shippedPresetNames();
    EXPECT_GE(names.size(), 5u);
    for (const std::string& name : names) {
        auto p = loadPreset(name);
        ASSERT_TRUE(p.ok()) << p.error().message;
        EXPECT_FALSE(p->elements.empty());
        EXPECT_FALSE(p->description.empty()) << name;
    }
}

TEST(Preset, TanczosClassicPlacesSecondariesWhereTheSeedDoes) {
    auto p = loadPreset("tanczos-classic");
    ASSERT_TRUE(p.ok());
    std::vector<float> main, secondary;
    for (const ElementParams& e : p->elements) (e.t == 1.f ? main : secondary).push_back(e.t);
    EXPECT_EQ(main.size(), 4u);  // glow, ring, streaks, rays
    std::sort(secondary.begin(), secondary.end());
    ASSERT_EQ(secondary.size(), 4u);
    EXPECT_NEAR(secondary[0], -1.f, 1e-4f);
    EXPECT_NEAR(secondary[1], -1.f / 1.2f, 1e-4f);
    EXPECT_NEAR(secondary[2], -0.5f, 1e-4f);
    EXPECT_NEAR(secondary[3], 1.f / 3.2f, 1e-4f);
}

TEST(Preset, ReportsTheFieldAndWhatWasExpected) {
    EXPECT_EQ(errorOf(std::string(R"({"elements":[)")
                          .append(kThree)
                          .append(R"({"type":"disc","size":"big"}]})")),
              R"(my.json: element[3].size: expected a number in [0, 4], got "big")");
    EXPECT_EQ(errorOf(R"({"elements":[{"type":"disc","size":5}]})"),
              "my.json: element[0].size: expected a number in [0, 4], got 5");
    EXPECT_EQ(errorOf(R"({"elements":[{"type":"rays","count":2.5}]})"),
              "my.json: element[0].count: expected an integer in [1, 4096], got 2.5");
    EXPECT_EQ(errorOf(R"({"elements":[{"type":"glow","color":[1,2]}]})"),
              "my.json: element[0].color: expected an array of 3 numbers in [0, 64], got [1,2]");
    EXPECT_EQ(
        errorOf(R"({"elements":[{"type":"sparkle"}]})"),
        R"(my.json: element[0].type: expected one of "glow", "ring", "streaks", "rays", "disc", "polygon", "edge-streak", "image", got "sparkle")");
    EXPECT_EQ(
        errorOf(R"({"elements":[{"size":0.1}]})").rfind("my.json: element[0].type: missing", 0),
        0u);
    EXPECT_EQ(
        errorOf(R"({"elements":[{"type":"glow","blend":"multiply"}]})"),
        R"(my.json: element[0].blend: expected one of "add", "screen", "over", got "multiply")");
    EXPECT_EQ(errorOf(R"({"elements":[], "x":1})"),
              "my.json: elements: expected an array of 1 to 256 elements, got []");
    EXPECT_EQ(
        errorOf(R"({"elemnts":[]})"),
        "my.json: elemnts: unknown key (expected one of: name, description, intensity, elements, "
        "source)");
    EXPECT_EQ(errorOf(R"({"name":"x"})"),
              "my.json: elements: missing; expected an array of elements");
    EXPECT_EQ(errorOf("[1,2]"), "my.json: (top level): expected an object, got [1,2]");
}

TEST(Preset, UnknownKeysAndKeysOfOtherTypesAreRejected) {
    const std::string e = errorOf(R"({"elements":[{"type":"glow","blades":6}]})");
    EXPECT_EQ(
        e.rfind(
            "my.json: element[0].blades: unknown key for a glow (expected one of: type, source, t, "
            "size",
            0),
        0u)
        << e;
    EXPECT_NE(errorOf(R"({"elements":[{"type":"glow","colour":[1,1,1]}]})")
                  .find("element[0].colour: unknown key"),
              std::string::npos);
}

TEST(Preset, BadJsonSaysWhere) {
    const std::string e = errorOf(R"({"elements": [ {"type": "glow",, } ]})");
    EXPECT_EQ(e.rfind("my.json: invalid JSON: parse error", 0), 0u) << e;
    EXPECT_NE(e.find("line 1"), std::string::npos) << e;
}

TEST(Preset, ValuesAndDefaultsAreApplied) {
    auto p = parsePreset(
        R"({"intensity":0.5,"elements":[{"type":"rays","count":7,"seed":99,"rotation":-45,"blend":"screen"}]})",
        "x.json");
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->name, "x");
    EXPECT_FLOAT_EQ(p->intensity, 0.5f);
    const ElementParams& e = p->elements[0];
    EXPECT_EQ(e.count, 7);
    EXPECT_EQ(e.seed, 99u);
    EXPECT_FLOAT_EQ(e.rotationDeg, -45.f);
    EXPECT_EQ(e.blend, BlendMode::Screen);
    EXPECT_FLOAT_EQ(e.t, 1.f);  // default
}

TEST(Preset, UnknownNameListsTheShippedOnes) {
    auto p = loadPreset("no-such-preset");
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("tanczos-classic"), std::string::npos) << p.error().message;
    auto missing = loadPreset("/nonexistent/dir/x.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::Io);
}

TEST(Preset, ParameterReferenceCoversEveryKey) {
    const std::string ref = presetParameterReference();
    for (const char* key : {"`t`", "`size`", "`color`", "`inner_color`", "`intensity`", "`aspect`",
                            "`rotation`", "`width`", "`softness`", "`count`", "`thickness`",
                            "`falloff`", "`min_length`", "`blades`", "`seed`", "`blend`"}) {
        EXPECT_NE(ref.find(key), std::string::npos) << key;
    }
}

TEST(Preset, AHiddenElementIsKeptAndSavedButNotDrawn) {
    // `visible: false` keeps the element (a designer's switched-off layer) and draws exactly
    // what the preset without it draws, on the CPU and in the spike-work estimate.
    const auto hidden = parsePreset(
        R"({"name": "h", "elements": [{"type": "glow", "size": 0.2},
            {"type": "streaks", "size": 0.5, "count": 64, "visible": false},
            {"type": "disc", "t": -0.5, "size": 0.05}]})",
        "h.json");
    ASSERT_TRUE(hidden.ok()) << hidden.error().message;
    EXPECT_FALSE(hidden->elements[1].visible);
    Preset without = *hidden;
    without.elements.erase(without.elements.begin() + 1);
    Image a(160, 90), b(160, 90);
    const FlareStats drawn = renderFlare(a, *hidden, {120.f, 30.f}, 1.f);
    renderFlare(b, without, {120.f, 30.f}, 1.f);
    EXPECT_EQ(drawn.elementsDrawn, 2u);
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160 * 4; ++x) ASSERT_EQ(a.row(y)[x], b.row(y)[x]) << x << "," << y;
    EXPECT_EQ(flareSpikeWork(*hidden, 1920, 1080), flareSpikeWork(without, 1920, 1080));
    // Saved only when false, and read back the same.
    const std::string json = presetToJson(*hidden);
    EXPECT_EQ(json.find("\"visible\":true"), std::string::npos);
    EXPECT_NE(json.find("\"visible\":false"), std::string::npos);
    EXPECT_FALSE(parsePreset(json, "again.json")->elements[1].visible);
    const auto bad =
        parsePreset(R"({"name": "h", "elements": [{"type": "glow", "visible": 1}]})", "bad.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("element[0].visible: expected true or false, got 1"),
              std::string::npos)
        << bad.error().message;
}
