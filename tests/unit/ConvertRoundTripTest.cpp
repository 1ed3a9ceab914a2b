// SPDX-License-Identifier: Apache-2.0
// flarekit convert, round trips: format -> flarekit -> format on the fixtures in examples/interop,
// every field compared as parsed JSON, YAML or Key=Value pairs; edits reaching the engine's file;
// baked elements coming back as themselves; every shipped preset out and back.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ConvertTestSupport.h"
#include "TempDir.h"

namespace flarekit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace test;

//! Numbers of two JSON values equal within float tolerance, everything else exactly.
void expectSameJson(const json& a, const json& b, const std::string& at) {
    if (a.is_number() && b.is_number()) {
        EXPECT_NEAR(a.get<double>(), b.get<double>(),
                    1e-5 * std::max(1.0, std::abs(a.get<double>())))
            << at;
        return;
    }
    if (a.is_object() && b.is_object()) {
        for (const auto& [k, v] : a.items()) {
            ASSERT_TRUE(b.contains(k)) << at << "." << k << " missing";
            expectSameJson(v, b[k], at + "." + k);
        }
        return;
    }
    if (a.is_array() && b.is_array()) {
        ASSERT_EQ(a.size(), b.size()) << at;
        for (std::size_t i = 0; i < a.size(); ++i)
            expectSameJson(a[i], b[i], at + "[" + std::to_string(i) + "]");
        return;
    }
    EXPECT_EQ(a, b) << at;
}

json yamlJson(const YAML::Node& n) {
    if (n.IsMap()) {
        json o = json::object();
        for (const auto& kv : n) o[kv.first.as<std::string>()] = yamlJson(kv.second);
        return o;
    }
    if (n.IsSequence()) {
        json a = json::array();
        for (const auto& v : n) a.push_back(yamlJson(v));
        return a;
    }
    if (!n.IsScalar()) return nullptr;
    const std::string s = n.as<std::string>();
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0' ? json(x) : json(s);
}

//! format -> flarekit -> format, through two files and the CLI's own code path.
std::string roundTrip(const std::string& input, const std::string& name, FlareFormat format,
                      TempDir& dir) {
    auto first = convertFlare(input, dir.file("fk/flare.json"), toFormat(FlareFormat::Flarekit));
    EXPECT_TRUE(first.ok()) << (first ? "" : first.error().message);
    ConvertOptions back;
    back.to = format;
    auto second = convertFlare(dir.file("fk/flare.json"), dir.file("back/" + name), back);
    EXPECT_TRUE(second.ok()) << (second ? "" : second.error().message);
    return dir.file("back/" + name);
}

TEST(Convert, JsonFormatsRoundTripEveryField) {
    const struct {
        const char* file;
        FlareFormat format;
    } cases[] = {{"babylon/sun-flares.json", FlareFormat::Babylon},
                 {"three/lensflare.json", FlareFormat::Three},
                 {"playcanvas/look.json", FlareFormat::PlayCanvas},
                 {"unreal/lensflare.json", FlareFormat::Unreal},
                 {"godot/settings.json", FlareFormat::Godot}};
    for (const auto& c : cases) {
        TempDir dir;
        const std::string out = roundTrip(kInterop + "/" + c.file, "out.json", c.format, dir);
        json original = json::parse(slurp(kInterop + "/" + c.file));
        const json written = json::parse(slurp(out));
        if (c.format == FlareFormat::Three) {
            // Hex colours are sRGB; they come back as the linear values three.js holds.
            for (json& e : original["elements"]) e.erase("color");
        }
        expectSameJson(original, written, c.file);
    }
}

TEST(Convert, UnityAssetsRoundTripEveryFieldAndKeepTheTexturesGuid) {
    TempDir dir;
    const std::string out = roundTrip(kInterop + "/unity/Assets/Flares/SunFlare.asset", "Sun.asset",
                                      FlareFormat::Unity, dir);
    const json a = yamlJson(YAML::LoadFile(kInterop + "/unity/Assets/Flares/SunFlare.asset"));
    const json b = yamlJson(YAML::LoadFile(out));
    expectSameJson(a, b, "SunFlare.asset");
    EXPECT_TRUE(fs::exists(dir.file("back/Ghost.png")));
    EXPECT_EQ(slurp(dir.file("back/Ghost.png.meta")),
              slurp(kInterop + "/unity/Assets/Flares/Ghost.png.meta"));
}

TEST(Convert, TextFormatsRoundTripEveryValue) {
    for (const auto& [file, format] : {std::pair{"unreal/lensflare.ini", FlareFormat::Unreal},
                                       std::pair{"godot/lens_flare.tscn", FlareFormat::Godot}}) {
        TempDir dir;
        const std::string name = fs::path(file).filename().string();
        const std::string out = roundTrip(kInterop + "/" + file, name, format, dir);
        // The same chain read back from either file, and the same Key = Value pairs.
        auto a = importFlare(kInterop + "/" + file), b = importFlare(out);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(postFxPresetToJson(a->chain).substr(20), postFxPresetToJson(b->chain).substr(20));
        auto pairs = [](const std::string& text) {
            std::map<std::string, std::string> kv;
            std::istringstream in(text);
            for (std::string line; std::getline(in, line);) {
                const auto eq = line.find('=');
                if (eq == std::string::npos || line[0] == '[' || line[0] == ';') continue;
                auto trim = [](std::string s) {
                    s.erase(0, s.find_first_not_of(' '));
                    s.erase(s.find_last_not_of(' ') + 1);
                    return s;
                };
                std::string v = trim(line.substr(eq + 1));
                // Numbers compared as numbers; colours as their components.
                std::string canon;
                for (std::size_t i = 0; i < v.size();) {
                    char* end = nullptr;
                    const double x = std::strtod(v.c_str() + i, &end);
                    if (end != v.c_str() + i &&
                        (std::isdigit((unsigned char)v[i]) || v[i] == '-')) {
                        canon += std::to_string(x);
                        i = std::size_t(end - v.c_str());
                    } else {
                        canon += v[i++];
                    }
                }
                kv[trim(line.substr(0, eq))] = canon;
            }
            return kv;
        };
        auto original = pairs(slurp(kInterop + "/" + file)), written = pairs(slurp(out));
        for (const auto& [k, v] : original) {
            if (k == "LensFlareTint") continue;  // its components in another order, below
            EXPECT_EQ(written[k], v) << file << ": " << k;
        }
    }
}

// Unreal accepts any flare position; flarekit's ghost scales end at 16 and 0.05 (|A| from
// 0.0625 to 20). A flare on the centre (A = 0) or beyond is drawn at the nearest position with
// one warning, and comes back as written, under the .ini's own section.
TEST(Convert, UnrealFlaresBeyondFlarekitsGhostScalesAreDrawnAtTheEndAndComeBackAsWritten) {
    TempDir dir;
    const std::string ini = dir.file("PostProcess.ini");
    spit(ini,
         "[/Script/MyGame.Settings]\nLensFlareIntensity=0.8\n"
         "LensFlareTints[0]=(R=1,G=0.6,B=0.3,A=0)\nLensFlareTints[1]=(R=1,G=1,B=1,A=-0.03)\n"
         "LensFlareTints[2]=(R=1,G=1,B=1,A=25)\nLensFlareTints[3]=(R=1,G=1,B=1,A=0.5)\n");
    auto imported = importFlare(ini);
    ASSERT_TRUE(imported.ok()) << imported.error().message;
    const auto& ghosts = imported->chain.ghosts;
    ASSERT_EQ(ghosts.size(), 8u);
    EXPECT_FLOAT_EQ(ghosts[0].scale, 16.f);
    EXPECT_FLOAT_EQ(ghosts[1].scale, -16.f);
    EXPECT_FLOAT_EQ(ghosts[2].scale, 0.05f);
    EXPECT_FLOAT_EQ(ghosts[3].scale, 2.f);
    int positionWarnings = 0;
    for (const std::string& w : imported->warnings)
        positionWarnings += w.find(".A ") != std::string::npos;
    EXPECT_EQ(positionWarnings, 3);

    const std::string back = roundTrip(ini, "Back.ini", FlareFormat::Unreal, dir);
    const std::string text = slurp(back);
    EXPECT_EQ(text.rfind("[/Script/MyGame.Settings]\n", 0), 0u) << text;
    for (const char* line : {"LensFlareTints[0]=(R=1.0,G=0.6,B=0.3,A=0.0)",
                             "LensFlareTints[1]=(R=1.0,G=1.0,B=1.0,A=-0.03)",
                             "LensFlareTints[2]=(R=1.0,G=1.0,B=1.0,A=25.0)",
                             "LensFlareTints[3]=(R=1.0,G=1.0,B=1.0,A=0.5)"})
        EXPECT_NE(text.find(line), std::string::npos) << line << " not in\n" << text;

    // Moved in flarekit, the ghost's own position is written instead of the kept one.
    FlareAsset moved = *imported;
    moved.chain.ghosts[0].scale = 4.f;
    ASSERT_TRUE(exportFlare(moved, dir.file("moved.ini"), FlareFormat::Unreal).ok());
    EXPECT_NE(slurp(dir.file("moved.ini")).find("LensFlareTints[0]=(R=1.0,G=0.6,B=0.3,A=0.25)"),
              std::string::npos)
        << slurp(dir.file("moved.ini"));
}

TEST(Convert, AnEditMadeInFlarekitReachesTheEnginesFile) {
    TempDir dir;
    auto asset = importFlare(kInterop + "/babylon/sun-flares.json");
    ASSERT_TRUE(asset.ok());
    asset->sprite.elements[1].t = 0.35f;
    asset->sprite.elements[1].color = {0.25f, 0.5f, 1.f};
    ASSERT_TRUE(exportFlare(*asset, dir.file("b.json"), FlareFormat::Babylon).ok());
    const json b = json::parse(slurp(dir.file("b.json")));
    EXPECT_NEAR(b["flares"][1]["position"].get<double>(), 0.35, 1e-6);
    EXPECT_NEAR(b["flares"][1]["color"][0].get<double>(), 0.25, 1e-6);
    EXPECT_EQ(b["flares"][6]["alphaMode"], 1);  // kept in source, written back
}

TEST(Convert, ProceduralElementsBakedForTextureEnginesComeBackAsThemselves) {
    TempDir dir;
    const FlareAsset asset = shippedSpriteAsset("tanczos-classic");
    ASSERT_FALSE(asset.sprite.elements.empty());
    const Preset* preset = &asset.sprite;
    ASSERT_TRUE(exportFlare(asset, dir.file("three.json"), FlareFormat::Three).ok());
    EXPECT_TRUE(fs::exists(dir.file("three-0-glow.png")));
    auto back = importFlare(dir.file("three.json"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->sprite.elements.size(), preset->elements.size());
    for (std::size_t i = 0; i < preset->elements.size(); ++i) {
        EXPECT_EQ(back->sprite.elements[i].type, preset->elements[i].type) << i;
        EXPECT_NEAR(back->sprite.elements[i].t, preset->elements[i].t, 1e-6) << i;
        EXPECT_NEAR(back->sprite.elements[i].size, preset->elements[i].size, 1e-6) << i;
    }
}

TEST(Convert, EveryShippedPresetExportsToEveryFormatOfItsKindAndReadsBack) {
    for (const std::string& name : shippedPresetNames()) {
        auto preset = loadPreset(name);
        ASSERT_TRUE(preset.ok());
        FlareAsset asset;
        asset.sprite = *preset;
        for (FlareFormat f : {FlareFormat::PlayCanvas, FlareFormat::Babylon, FlareFormat::Three,
                              FlareFormat::Unity}) {
            TempDir dir;
            const std::string out =
                dir.file(f == FlareFormat::Unity ? "flare.asset" : "flare.json");
            auto warnings = exportFlare(asset, out, f);
            ASSERT_TRUE(warnings.ok()) << name << " " << warnings.error().message;
            ConvertOptions from;
            from.from = f;
            auto back = importFlare(out, from);
            ASSERT_TRUE(back.ok()) << name << " " << back.error().message;
            EXPECT_EQ(back->sprite.elements.size(), preset->elements.size()) << name;
            for (std::size_t i = 0; i < preset->elements.size(); ++i)
                EXPECT_NEAR(back->sprite.elements[i].t, preset->elements[i].t, 1e-5)
                    << name << " " << kFlareFormatNames[int(f)] << " " << i;
        }
    }
    for (const std::string& name : shippedPostFxPresetNames()) {
        auto chain = loadPostFxPreset(name);
        ASSERT_TRUE(chain.ok());
        FlareAsset asset;
        asset.postFx = true;
        asset.chain = *chain;
        for (const char* file : {"flare.ini", "flare.tscn"}) {
            TempDir dir;
            auto warnings = exportFlare(asset, dir.file(file),
                                        file[6] == 'i' ? FlareFormat::Unreal : FlareFormat::Godot);
            ASSERT_TRUE(warnings.ok()) << name << " " << warnings.error().message;
            auto back = importFlare(dir.file(file));
            ASSERT_TRUE(back.ok()) << name << " " << back.error().message;
            EXPECT_NEAR(back->chain.flareIntensity, chain->flareIntensity, 1e-5) << name;
        }
    }
}

TEST(Convert, AUnityProjectsOwnMetaBesideTheOutputKeepsItsGuid) {
    TempDir dir;
    const FlareAsset asset = shippedSpriteAsset("hexagon-ghosts");
    ASSERT_FALSE(asset.sprite.elements.empty());
    ASSERT_TRUE(exportFlare(asset, dir.file("Flare.asset"), FlareFormat::Unity).ok());
    // The glow was baked (Unity has no glow shape) with a .meta; the project re-imported it
    // under a GUID of its own.
    const std::string meta = dir.file("Flare-0-glow.png.meta");
    ASSERT_TRUE(fs::exists(meta));
    const std::string mine = "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n";
    spit(meta, mine);
    ASSERT_TRUE(exportFlare(asset, dir.file("Flare.asset"), FlareFormat::Unity).ok());
    EXPECT_EQ(slurp(meta), mine);
    EXPECT_NE(slurp(dir.file("Flare.asset")).find("guid: 0123456789abcdef0123456789abcdef"),
              std::string::npos);
}

}  // namespace
}  // namespace flarekit
