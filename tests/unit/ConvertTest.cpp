// SPDX-License-Identifier: Apache-2.0
// flarekit convert: each engine's position and size conventions checked by rendering the
// imported element and finding it where that engine's own formula puts it (a light in a
// corner, two aspect ratios); round trips format -> flarekit -> format on the fixtures in
// examples/interop; renders of imported presets against the same elements written by hand;
// bad input as one line naming the file and the field, with nothing written.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "TempDir.h"
#include "flarekit/Convert.h"
#include "flarekit/ImageIO.h"

namespace flarekit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::TempDir;

const std::string kData = std::string(FLAREKIT_SOURCE_DIR) + "/examples/interop";

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void spit(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

ConvertOptions toFormat(FlareFormat f) {
    ConvertOptions o;
    o.to = f;
    return o;
}
ConvertOptions fromFormat(FlareFormat f) {
    ConvertOptions o;
    o.from = f;
    return o;
}

//! A white 16x16 square texture, so an image element covers exactly its quad.
void writeSquareTexture(const std::string& path) {
    Image square(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) square.at(x, y) = {1, 1, 1, 1};
    ASSERT_TRUE(writeImage(path, square).ok());
}

struct Drawn {
    double cx = 0, cy = 0;         //!< centroid of what was drawn
    double width = 0, height = 0;  //!< its extent (pixels above half the peak)
    double fullWidth = 0;          //!< its whole extent, soft edge included (above 0.1%)
};

Drawn render(const Preset& preset, int w, int h, Point light) {
    Image image(w, h);
    renderFlare(image, preset, light, 1.f);
    double sum = 0, peak = 0;
    Drawn d;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double v = image.at(x, y).g;
            peak = std::max(peak, v);
            sum += v;
            d.cx += v * (x + 0.5);
            d.cy += v * (y + 0.5);
        }
    d.cx /= sum;
    d.cy /= sum;
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.at(x, y).g > 0.5 * peak) {
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    d.width = x1 - x0 + 1;
    d.height = y1 - y0 + 1;
    int f0 = w, f1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.at(x, y).g > 1e-3 * peak) f0 = std::min(f0, x), f1 = std::max(f1, x);
    d.fullWidth = f1 - f0 + 1;
    return d;
}

Preset importSprite(const std::string& path, const ConvertOptions& options = {}) {
    auto asset = importFlare(path, options);
    EXPECT_TRUE(asset.ok()) << (asset ? "" : asset.error().message);
    return asset ? asset->sprite : Preset{};
}

// A light near the top-left corner of a 640x360 frame (clip space: x -0.9, y +0.8).
constexpr int kW = 640, kH = 360;
const Point kLight{32.f, 36.f};
double clipX(double px) {
    return 2.0 * px / kW - 1.0;
}
double clipY(double py) {
    return 1.0 - 2.0 * py / kH;
}
double pixelX(double cx) {
    return (cx + 1.0) * kW / 2.0;
}
double pixelY(double cy) {
    return (1.0 - cy) * kH / 2.0;
}

TEST(Convert, BabylonPlacesAFlareWhereLensFlareSystemDrawsIt) {
    TempDir dir;
    writeSquareTexture(dir.file("sq.png"));
    for (double position : {0.0, 0.5, -0.7}) {
        spit(dir.file("b.json"), R"({"flares":[{"size":0.05,"position":)" +
                                     std::to_string(position) +
                                     R"(,"color":[1,1,1],"textureName":"sq.png"}]})");
        const Drawn d = render(importSprite(dir.file("b.json")), kW, kH, kLight);
        // lensFlareSystem.ts: x = centerX - (centerX - lightX) * position.
        EXPECT_NEAR(d.cx, kW / 2.0 - (kW / 2.0 - kLight.x) * position, 0.5) << position;
        EXPECT_NEAR(d.cy, kH / 2.0 - (kH / 2.0 - kLight.y) * position, 0.5) << position;
    }
}

TEST(Convert, ThreeJsPlacesAnElementWhereLensflareDrawsIt) {
    TempDir dir;
    writeSquareTexture(dir.file("sq.png"));
    for (double distance : {0.0, 0.25, 0.8}) {
        spit(dir.file("t.json"), R"({"elements":[{"texture":"sq.png","size":20,"distance":)" +
                                     std::to_string(distance) + "}]}");
        const Drawn d = render(importSprite(dir.file("t.json")), kW, kH, kLight);
        // Lensflare.js: positionScreen + (-2 positionScreen) x distance, in clip space.
        EXPECT_NEAR(d.cx, pixelX(clipX(kLight.x) * (1 - 2 * distance)), 0.5) << distance;
        EXPECT_NEAR(d.cy, pixelY(clipY(kLight.y) * (1 - 2 * distance)), 0.5) << distance;
    }
}

std::string unityAsset(const std::string& element) {
    return "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &11400000\nMonoBehaviour:\n"
           "  m_Name: t\n  elements:\n  - " +
           element + "\n";
}

TEST(Convert, UnityPlacesAnElementWhereLensFlareCommonSrpDrawsIt) {
    TempDir dir;
    for (double position : {0.0, 0.3, 0.9}) {
        spit(dir.file("u.asset"),
             unityAsset("flareType: 2\n    m_SideCount: 4\n    m_EdgeOffset: 1\n    position: " +
                        std::to_string(position) + "\n    uniformScale: 0.4"));
        const Drawn d = render(importSprite(dir.file("u.asset")), kW, kH, kLight);
        // LensFlareCommonSRP: screenPos x (1 - 2 x position) in clip space.
        EXPECT_NEAR(d.cx, pixelX(clipX(kLight.x) * (1 - 2 * position)), 0.5) << position;
        EXPECT_NEAR(d.cy, pixelY(clipY(kLight.y) * (1 - 2 * position)), 0.5) << position;
    }
}

TEST(Convert, PlayCanvasOffsetRunsFromTheLightThroughTheCentre) {
    TempDir dir;
    for (double offset : {0.0, 1.0, 1.6}) {
        spit(dir.file("p.json"), R"({"elements":[{"shape":"circle","size":0.05,"offset":)" +
                                     std::to_string(offset) + "}]}");
        const Drawn d = render(importSprite(dir.file("p.json")), kW, kH, kLight);
        EXPECT_NEAR(d.cx, kLight.x + (kW / 2.0 - kLight.x) * offset, 0.5) << offset;
        EXPECT_NEAR(d.cy, kLight.y + (kH / 2.0 - kLight.y) * offset, 0.5) << offset;
    }
}

// Sizes through each engine's screen geometry, at 16:9 and 4:3 (same height, 360 px).
TEST(Convert, SizesFollowEachEnginesScreenGeometryAtTwoAspects) {
    TempDir dir;
    writeSquareTexture(dir.file("sq.png"));
    const Point centre{0, 0};
    for (int w : {640, 480}) {
        ConvertOptions options;
        options.aspect = float(w) / kH;
        options.referenceHeight = kH;
        const Point light{float(w) / 2.f, float(kH) / 2.f};
        (void)centre;
        // Babylon: a square of half side size x W / 4 pixels.
        spit(dir.file("b.json"),
             R"({"flares":[{"size":0.2,"position":1,"color":[1,1,1],"textureName":"sq.png"}]})");
        Drawn d = render(importSprite(dir.file("b.json"), options), w, kH, light);
        EXPECT_NEAR(d.width, 0.2 * w / 2.0, 1.0) << w;
        EXPECT_NEAR(d.height, 0.2 * w / 2.0, 1.0) << w;
        // three.js: `size` pixels a side at the reference height.
        spit(dir.file("t.json"), R"({"elements":[{"texture":"sq.png","size":90}]})");
        d = render(importSprite(dir.file("t.json"), options), w, kH, light);
        EXPECT_NEAR(d.width, 90, 1.0) << w;
        // Unity: 0.1 x uniformScale x sizeXY.y frame heights a side, x by sizeXY.x.
        spit(dir.file("u.asset"), unityAsset("flareType: 2\n    m_SideCount: 4\n    m_EdgeOffset: 1"
                                             "\n    rotation: 45\n    uniformScale: 2\n"
                                             "    sizeXY: {x: 1, y: 1}"));
        d = render(importSprite(dir.file("u.asset"), options), w, kH, light);
        // A square turned 45 degrees: its circumradius is the quad's half height.
        EXPECT_NEAR(d.height, 2 * 0.1 * 2 * kH / 2.0, 2.0) << w;
        // PlayCanvas: `size` is the diameter in frame heights.
        spit(dir.file("p.json"), R"({"elements":[{"shape":"circle","size":0.4,"offset":0}]})");
        d = render(importSprite(dir.file("p.json"), options), w, kH, light);
        EXPECT_NEAR(d.fullWidth, 0.4 * kH, 2.0) << w;
    }
}

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
        const std::string out = roundTrip(kData + "/" + c.file, "out.json", c.format, dir);
        json original = json::parse(slurp(kData + "/" + c.file));
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
    const std::string out = roundTrip(kData + "/unity/Assets/Flares/SunFlare.asset", "Sun.asset",
                                      FlareFormat::Unity, dir);
    const json a = yamlJson(YAML::LoadFile(kData + "/unity/Assets/Flares/SunFlare.asset"));
    const json b = yamlJson(YAML::LoadFile(out));
    expectSameJson(a, b, "SunFlare.asset");
    EXPECT_TRUE(fs::exists(dir.file("back/Ghost.png")));
    EXPECT_EQ(slurp(dir.file("back/Ghost.png.meta")),
              slurp(kData + "/unity/Assets/Flares/Ghost.png.meta"));
}

TEST(Convert, TextFormatsRoundTripEveryValue) {
    for (const auto& [file, format] : {std::pair{"unreal/lensflare.ini", FlareFormat::Unreal},
                                       std::pair{"godot/lens_flare.tscn", FlareFormat::Godot}}) {
        TempDir dir;
        const std::string name = fs::path(file).filename().string();
        const std::string out = roundTrip(kData + "/" + file, name, format, dir);
        // The same chain read back from either file, and the same Key = Value pairs.
        auto a = importFlare(kData + "/" + file), b = importFlare(out);
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
        auto original = pairs(slurp(kData + "/" + file)), written = pairs(slurp(out));
        for (const auto& [k, v] : original) {
            if (k == "LensFlareTint") continue;  // its components in another order, below
            EXPECT_EQ(written[k], v) << file << ": " << k;
        }
    }
}

TEST(Convert, AnEditMadeInFlarekitReachesTheEnginesFile) {
    TempDir dir;
    auto asset = importFlare(kData + "/babylon/sun-flares.json");
    ASSERT_TRUE(asset.ok());
    asset->sprite.elements[1].t = 0.35f;
    asset->sprite.elements[1].color = {0.25f, 0.5f, 1.f};
    ASSERT_TRUE(exportFlare(*asset, dir.file("b.json"), FlareFormat::Babylon).ok());
    const json b = json::parse(slurp(dir.file("b.json")));
    EXPECT_NEAR(b["flares"][1]["position"].get<double>(), 0.35, 1e-6);
    EXPECT_NEAR(b["flares"][1]["color"][0].get<double>(), 0.25, 1e-6);
    EXPECT_EQ(b["flares"][6]["alphaMode"], 1);  // kept in source, written back
}

TEST(Convert, AnImportedLookRendersAsTheSameElementsWrittenByHand) {
    // PlayCanvas's look.json, written by hand in flarekit's terms: t = 1 - offset, size halved,
    // each shape's element, the polygon's 3 copies spread 0.4 about offset 1.4.
    const std::string hand = R"({"elements":[
      {"type":"glow","t":1,"size":0.25,"color":[1,0.85,0.6],"inner_color":[1,0.85,0.6],"intensity":1.2},
      {"type":"ring","t":1,"size":0.15,"color":[0.5,0.4,0.9],"intensity":0.4},
      {"type":"polygon","t":-0.2,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"polygon","t":-0.4,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"polygon","t":-0.6,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"disc","t":-0.8,"size":0.1,"aspect":1.2,"color":[0.7,0.4,0.8],"inner_color":[0.7,0.4,0.8],"intensity":0.25},
      {"type":"image","t":1,"size":0.45,"aspect":4,"color":[0.8,0.9,1],"intensity":0.5,"texture":"streak.png"}]})";
    auto byHand = parsePreset(hand, kData + "/playcanvas/hand.json");
    ASSERT_TRUE(byHand.ok()) << byHand.error().message;
    const Preset imported = importSprite(kData + "/playcanvas/look.json");
    Image a(kW, kH), b(kW, kH);
    renderFlare(a, imported, kLight, 1.f);
    renderFlare(b, *byHand, kLight, 1.f);
    float worst = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            worst = std::max({worst, std::abs(a.at(x, y).r - b.at(x, y).r),
                              std::abs(a.at(x, y).g - b.at(x, y).g),
                              std::abs(a.at(x, y).b - b.at(x, y).b)});
    EXPECT_LT(worst, 1e-5f);
}

TEST(Convert, WhatDoesNotMapIsOneWarningEachAndKeptInSource) {
    auto asset = importFlare(kData + "/unity/Assets/Flares/SunFlare.asset");
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
    auto current = importFlare(kData + "/unity/Assets/Flares/SunFlare.asset");
    ConvertOptions earlyOrder;
    earlyOrder.unityBlendOrder = UnityBlendOrder::Early;
    auto early = importFlare(kData + "/unity/Assets/Flares/EarlyFlare.asset", earlyOrder);
    ASSERT_TRUE(current.ok() && early.ok());
    EXPECT_EQ(current->sprite.elements[4].blend, BlendMode::Screen);  // 1: Screen (12.0+)
    EXPECT_EQ(early->sprite.elements[0].blend, BlendMode::Add);       // 1: Additive (early)
    EXPECT_EQ(early->sprite.elements[1].blend, BlendMode::Screen);    // 3: Screen (early)
}

TEST(Convert, BadInputIsOneLineNamingTheFileAndFieldAndWritesNothing) {
    TempDir dir;
    writeSquareTexture(dir.file("sq.png"));
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
    auto r = convertFlare(kData + "/babylon/sun-flares.json", dir.file("out/x.json"),
                          toFormat(FlareFormat::Flarekit));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(slurp(dir.file("out/flare.png")), "the user's own file");
    EXPECT_FALSE(fs::exists(dir.file("out/x.json")));
    EXPECT_FALSE(fs::exists(dir.file("out/flare3.png")));
}

TEST(Convert, ProceduralElementsBakedForTextureEnginesComeBackAsThemselves) {
    TempDir dir;
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    FlareAsset asset;
    asset.sprite = *preset;
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

}  // namespace
}  // namespace flarekit

namespace flarekit {
namespace {

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

namespace flarekit {
namespace {

TEST(Convert, AUnityProjectsOwnMetaBesideTheOutputKeepsItsGuid) {
    TempDir dir;
    auto preset = loadPreset("hexagon-ghosts");
    ASSERT_TRUE(preset.ok());
    FlareAsset asset;
    asset.sprite = *preset;
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

namespace flarekit {
namespace {

//! Coverage of a rounded polygon against its definition: inside exactly where the distance to
//! the polygon of apothem (1 - r) cos(pi/N) is under r cos(pi/N).
TEST(Convert, RoundedPolygonsAreThePolygonGrownByADisc) {
    ElementParams p = defaultElement(ElementType::Polygon);
    p.blades = 5;
    p.softness = 0.f;
    p.intensity = 1.f;
    p.color = {1, 1, 1};
    p.innerColor = Rgb{1, 1, 1};
    for (float r : {0.f, 0.3f, 1.f}) {
        p.roundness = r;
        const float radius = 100.f;
        const Image img = renderElement(p, radius);
        const double apothem = std::cos(std::numbers::pi / 5), inner = apothem * (1 - r);
        int wrong = 0, checked = 0;
        for (int y = 0; y < img.height(); y += 3)
            for (int x = 0; x < img.width(); x += 3) {
                const double px = (x + 0.5 - img.width() / 2.0) / radius,
                             py = (y + 0.5 - img.height() / 2.0) / radius;
                // Distance to the inner polygon: the largest over its edges of the distance
                // past each edge, exact off the corners; near corners, to the corner point.
                double dist = 0;
                for (int i = 0; i < 5; ++i) {
                    const double a = 2 * std::numbers::pi * i / 5;
                    const double along = px * std::cos(a) + py * std::sin(a) - inner;
                    const double across = std::abs(-px * std::sin(a) + py * std::cos(a)) -
                                          inner * std::tan(std::numbers::pi / 5);
                    if (along <= 0) continue;
                    dist = std::max(dist, across > 0 ? std::hypot(along, across) : along);
                }
                const double margin = 1.5 / radius;  // antialiasing band
                const double d = dist - apothem * r;
                if (std::abs(d) < margin) continue;
                ++checked;
                const bool inside = img.at(x, y).a > 0.5f;
                wrong += inside != (d < 0);
            }
        EXPECT_EQ(wrong, 0) << r;
        EXPECT_GT(checked, 1000);
    }
}

}  // namespace
}  // namespace flarekit
