// SPDX-License-Identifier: Apache-2.0
// flarekit convert, input: what does not map is one warning each and kept in source; Unity's
// blend modes in either package order; bad input as one line naming the file and the field, with
// nothing written; a user's file beside the output never replaced.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "ConvertTestSupport.h"
#include "TempDir.h"

namespace flarekit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace test;

TEST(Convert, WhatDoesNotMapIsOneWarningEachAndKeptInSource) {
    auto asset = importFlare(kInterop + "/unity/Assets/Flares/SunFlare.asset");
    ASSERT_TRUE(asset.ok());
    ASSERT_EQ(asset->warnings.size(), 1u);
    EXPECT_NE(asset->warnings[0].find("elements[0].m_FallOff 0.5"), std::string::npos);
    // The uniform count of 3 drawn as three copies 2 x lengthSpread / 2 apart in u.
    const auto& e = asset->sprite.elements;
    ASSERT_EQ(e.size(), 6u);
    EXPECT_NEAR(e[1].t, 1 - 1.4, 1e-6);
    EXPECT_NEAR(e[2].t, 1 - 1.6, 1e-6);
    EXPECT_NEAR(e[3].t, 1 - 1.8, 1e-6);
    EXPECT_NE(e[0].source.find("\"m_FallOff\":\"0.5\""), std::string::npos);
    EXPECT_FLOAT_EQ(e[5].roundness, 0.3f);  // m_SdfRoundness: flarekit's polygon roundness
    // Each copy's colour: the tint x the gradient (orange to white) at 0, 1/2, 1.
    EXPECT_NEAR(e[1].color[1], 0.8f * 0.5f, 1e-6);
    EXPECT_NEAR(e[2].color[1], 0.8f * 0.75f, 1e-6);
    EXPECT_NEAR(e[3].color[1], 0.8f * 1.f, 1e-6);
    EXPECT_NEAR(e[2].color[2], 0.6f * 0.6f, 1e-6);
}

TEST(Convert, UnityBlendModesReadInEitherPackageOrder) {
    auto current = importFlare(kInterop + "/unity/Assets/Flares/SunFlare.asset");
    ConvertOptions earlyOrder;
    earlyOrder.unityBlendOrder = UnityBlendOrder::Early;
    auto early = importFlare(kInterop + "/unity/Assets/Flares/EarlyFlare.asset", earlyOrder);
    ASSERT_TRUE(current.ok() && early.ok());
    EXPECT_EQ(current->sprite.elements[4].blend, BlendMode::Screen);  // 1: Screen (12.0+)
    EXPECT_EQ(early->sprite.elements[0].blend, BlendMode::Add);       // 1: Additive (early)
    EXPECT_EQ(early->sprite.elements[1].blend, BlendMode::Screen);    // 3: Screen (early)
}

TEST(Convert, BadInputIsOneLineNamingTheFileAndFieldAndWritesNothing) {
    TempDir dir;
    ASSERT_TRUE(writeSquareTexture(dir.file("sq.png")));
    const auto errorOf = [&](const std::string& name, const std::string& text,
                             ConvertOptions options = {}) {
        spit(dir.file(name), text);
        if (!options.to) options.to = FlareFormat::Flarekit;
        auto r = convertFlare(dir.file(name), dir.file("out/x.json"), options);
        EXPECT_FALSE(fs::exists(dir.file("out"))) << name;
        return r ? std::string("ok") : r.error().message;
    };
    const std::string b = dir.file("b.json");
    EXPECT_EQ(
        errorOf("b.json", R"({"flares":[{"size":"big","position":0,"textureName":"sq.png"}]})"),
        b + ": flares[0].size: expected a number in [0, 100], got \"big\"");
    EXPECT_EQ(
        errorOf("b.json", R"({"flares":[{"size":0.1,"position":0,"textureName":"gone.png"}]})"),
        b + ": flares[0].textureName: expected the texture file 'gone.png' beside b.json, '" +
            dir.file("gone.png") + "' does not exist");
    EXPECT_EQ(errorOf("u.asset", unityAsset("flareType: 1\n    blendMode: 7")),
              dir.file("u.asset") +
                  ": MonoBehaviour.elements[0].blendMode: expected 0 to 3 "
                  "(additive, screen, premultiply, lerp), got \"7\"");
    EXPECT_EQ(errorOf("u.asset", unityAsset("flareType: 0\n    lensFlareTexture: {fileID: 2800000, "
                                            "guid: 0123456789abcdef0123456789abcdef, type: 3}"))
                  .find("lensFlareTexture: expected the texture of guid 0123456789abcdef"),
              dir.file("u.asset").size() + 2 + std::string("MonoBehaviour.elements[0].").size());
    // A file of another format named as Babylon.
    EXPECT_EQ(errorOf("t.json", R"({"elements":[{"texture":"sq.png","size":10}]})",
                      fromFormat(FlareFormat::Babylon)),
              dir.file("t.json") +
                  ": flares: expected an array of 1 to 256 flares of a Babylon.js LensFlareSystem");
    // Sprite elements cannot become a post-process chain.
    spit(dir.file("b.json"), R"({"flares":[{"size":0.1,"position":0,"textureName":"sq.png"}]})");
    auto r = convertFlare(dir.file("b.json"), dir.file("out/x.ini"), {});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("unreal holds post-process (screen-space) flares"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(dir.file("out")));
}

TEST(Convert, ADifferentTextureAlreadyBesideTheOutputIsNeverReplaced) {
    TempDir dir;
    fs::create_directories(dir.file("out"));
    spit(dir.file("out/flare.png"), "the user's own file");
    auto r = convertFlare(kInterop + "/babylon/sun-flares.json", dir.file("out/x.json"),
                          toFormat(FlareFormat::Flarekit));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(slurp(dir.file("out/flare.png")), "the user's own file");
    EXPECT_FALSE(fs::exists(dir.file("out/x.json")));
    EXPECT_FALSE(fs::exists(dir.file("out/flare3.png")));
}

TEST(Convert, ValuesOfTheWrongTypeAreBadInputNotACrash) {
    TempDir dir;
    spit(dir.file("b.json"), R"({"name":5,"flares":[{"size":0.1,"position":0,"textureName":7}]})");
    auto r = importFlare(dir.file("b.json"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(r.error().message,
              dir.file("b.json") + ": flares[0].textureName: expected a string, got 7");
    // A tag holding a comma right after `---` makes yaml-cpp 0.7 loop forever: refused first.
    spit(dir.file("t.asset"), "%YAML 1.1\n--- !a,b\nMonoBehaviour:\n  elements: []\n");
    r = importFlare(dir.file("t.asset"));
    ASSERT_FALSE(r.ok());
    spit(dir.file("t.asset"), "--- !u!114 &1\nMonoBehaviour:\n  m_Name: !x,y\n");
    r = importFlare(dir.file("t.asset"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(
        r.error().message,
        dir.file("t.asset") + ": line 3: expected no YAML tag inside a Unity asset's document");
    spit(dir.file("u.asset"), unityAsset("flareType: 0\n    lensFlareTexture: {guid: {a: 1}}"));
    r = importFlare(dir.file("u.asset"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
}

}  // namespace
}  // namespace flarekit
