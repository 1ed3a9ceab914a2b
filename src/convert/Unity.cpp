// SPDX-License-Identifier: Apache-2.0
// Unity Lens Flare (SRP) data assets (LensFlareDataSRP, a YAML .asset). What Unity's renderer
// does with an element (LensFlareCommonSRP.cs of the SRP core package, 12.x to 17.x):
//  - position: drawn at screenPos x (1 - 2 x position) in clip space, so u = 2 x position
//    (0 on the light, 0.5 at the centre, 1 at the mirror point);
//  - size: the quad's half extent is 0.1 x uniformScale x sizeXY (its "arbitrary" scaleSize)
//    in clip-space heights (x is corrected by the screen ratio), so the radius is
//    0.05 x uniformScale x sizeXY.y frame heights and the aspect sizeXY.x / sizeXY.y;
//  - circle and polygon: 1 inside, easing to 0 over the outer (1 - edgeOffset) of the radius;
//  - count > 1 with a uniform distribution: copies at position + i x 2 lengthSpread/(count-1)
//    (in u), each turned uniformAngle more than the last.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <sstream>

#include "convert/ConvertCommon.h"
#include "convert/UnityMeta.h"
#include "flarekit/ParamText.h"

namespace flarekit::convert {

namespace {

//! The LensFlareDataSRP script's GUID in the SRP core package (its shipped "Default Lens Flare
//! (SRP)" asset names it): what m_Script points to in an asset flarekit writes.
constexpr const char* kLensFlareScriptGuid = "877e1507ae8d81c40bf1b94c1a86036f";
//! Unity's flare quad half extent per unit of uniformScale x sizeXY (LensFlareCommonSRP's
//! scaleSize 0.1), in clip-space units of which the frame height has 2: 0.05 frame heights.
constexpr double kUnitySizeToRadius = 0.05;

enum UnityType { kImage = 0, kCircle = 1, kPolygon = 2, kRing = 3, kNested = 4 };

//! Nodes converted from one asset at most: a flare asset has ~10^3 (curves included); the bound
//! stops an alias-laden file from expanding exponentially (YAML's "billion laughs").
constexpr std::size_t kMaxYamlNodes = std::size_t(1) << 20;
//! Nesting deeper than a flare asset's (curves' keys sit at depth 6) is refused: a recursion bound.
constexpr int kMaxYamlDepth = 64;

struct YamlBudget {
    std::size_t nodes = 0;
    bool exceeded = false;
};

json yamlToJson(const YAML::Node& n, YamlBudget& budget, int depth = 0) {
    if (++budget.nodes > kMaxYamlNodes || depth > kMaxYamlDepth) {
        budget.exceeded = true;
        return nullptr;
    }
    if (n.IsMap()) {
        json o = json::object();
        for (const auto& kv : n) {
            o[kv.first.IsScalar() ? kv.first.as<std::string>() : std::string("?")] =
                yamlToJson(kv.second, budget, depth + 1);
            if (budget.exceeded) return nullptr;
        }
        return o;
    }
    if (n.IsSequence()) {
        json a = json::array();
        for (const auto& v : n) {
            a.push_back(yamlToJson(v, budget, depth + 1));
            if (budget.exceeded) return nullptr;
        }
        return a;
    }
    if (n.IsScalar()) return n.as<std::string>();
    return nullptr;
}

//! Unity's assets are YAML documents each headed `--- !u!CLASS &ID`, with no tag inside: the
//! bodies are cut out here and each parsed alone, so that the parser never sees a tag or a
//! directive. (yaml-cpp 0.7 loops forever on a tag holding a comma right after `---`, which a
//! hostile file can carry; no flare asset has one.) One line naming a tag that is refused.
Result<std::vector<std::string>> unityDocuments(const std::string& text, const std::string& path) {
    std::vector<std::string> bodies;
    std::istringstream in(text);
    std::string line, body;
    bool inDocument = false;
    int lineNo = 0;
    for (; std::getline(in, line); ++lineNo) {
        if (line.rfind("---", 0) == 0) {
            if (inDocument) bodies.push_back(body);
            body.clear();
            inDocument = true;
            continue;
        }
        if (!inDocument && (line.empty() || line[0] == '%' || line[0] == '#')) continue;
        if (!inDocument) inDocument = true;  // a document without a header
        // A tag starts with '!' after a space, a flow indicator or the line's start, outside
        // quotes; Unity writes none inside a document.
        char quote = 0;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (quote) {
                if (c == quote) quote = 0;
                continue;
            }
            if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '#' && (i == 0 || line[i - 1] == ' ')) {
                break;  // a comment
            } else if (c == '!' &&
                       (i == 0 || std::string(" [{,:-").find(line[i - 1]) != std::string::npos)) {
                return invalidInput(path + ": line " + std::to_string(lineNo + 1) +
                                    ": expected no YAML tag inside a Unity asset's document");
            }
        }
        body += line;
        body += '\n';
    }
    if (inDocument) bodies.push_back(body);
    return bodies;
}

void emitJson(YAML::Emitter& out, const json& v) {
    if (v.is_object()) {
        // Unity writes small maps of numbers ({x: 0, y: 0}, {fileID: 0}) in flow style.
        bool flat = !v.empty() && v.size() <= 4;
        for (const auto& [k, x] : v.items()) flat = flat && !x.is_structured();
        out << (flat ? YAML::Flow : YAML::Block) << YAML::BeginMap;
        for (const auto& [k, x] : v.items()) {
            out << YAML::Key << k << YAML::Value;
            emitJson(out, x);
        }
        out << YAML::EndMap;
    } else if (v.is_array()) {
        out << YAML::Block << YAML::BeginSeq;
        for (const json& x : v) emitJson(out, x);
        out << YAML::EndSeq;
    } else if (v.is_string()) {
        out << v.get<std::string>();
    } else if (v.is_number() || v.is_boolean()) {
        out << v.dump();
    } else {
        out << YAML::Null;
    }
}

std::string unityNumber(double x) {
    std::ostringstream os;
    os.precision(9);
    os << tidy(x);
    return os.str();
}

//! A numeric field of a YAML element under its current name or its pre-12.0 one.
struct Fields {
    const json& e;
    const JsonPlace& at;
    const json* find(std::initializer_list<const char*> names) const {
        for (const char* n : names)
            if (auto it = e.find(n); it != e.end()) return &*it;
        return nullptr;
    }
    Result<double> number(std::initializer_list<const char*> names, double fallback,
                          double min = -1e9, double max = 1e9) const {
        const json* v = find(names);
        if (!v) return fallback;
        const std::string s = v->is_string() ? v->get<std::string>() : std::string();
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !std::isfinite(x) || x < min || x > max)
            return (at / *names.begin())
                .fail(joinText("expected a number in ", formatParamRange(min, max), ", got ",
                               jsonExcerpt(*v)));
        return x;
    }
    Result<double> component(const char* name, const char* key, double fallback) const {
        const json* v = find({name});
        if (!v) return fallback;
        if (!v->is_object() || !v->contains(key))
            return (at / name).fail(std::string("expected a map with ") + key + ", got " +
                                    jsonExcerpt(*v));
        return Fields{*v, at / name}.number({key}, fallback);
    }
};

Result<Rgb> tintOf(const Fields& f, const JsonPlace& at) {
    const json* t = f.find({"tint"});
    if (!t) return Rgb{1, 1, 1};
    Rgb c{};
    for (int i = 0; i < 3; ++i) {
        auto x = f.component("tint", i == 0 ? "r" : i == 1 ? "g" : "b", 1.0);
        if (!x) return x.error();
        if (*x < 0 || *x > 1000) return (at / "tint").fail("expected colour components >= 0");
        c[std::size_t(i)] = float(*x);
    }
    return c;
}

//! Unity's Gradient (colorGradient: key0..7 with ctime0..7 in 0..65535, m_NumColorKeys,
//! m_Mode 0 blend / 1 fixed) at t in [0, 1]; white where the asset has none.
Rgb gradientAt(const json& g, double t) {
    const auto num = [&](const std::string& key, double fallback) {
        const std::string s = fieldOr(g, key.c_str(), std::string());
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        return !s.empty() && *end == '\0' && std::isfinite(x) ? x : fallback;
    };
    const auto key = [&](int i) {
        const json& k = g.is_object() && g.contains("key" + std::to_string(i))
                            ? g["key" + std::to_string(i)]
                            : json();
        const auto c = [&](const char* n) {
            const std::string s = fieldOr(k, n, std::string("1"));
            return float(std::clamp(std::strtod(s.c_str(), nullptr), 0.0, 1000.0));
        };
        return Rgb{c("r"), c("g"), c("b")};
    };
    const int n = int(std::clamp(num("m_NumColorKeys", 0), 0.0, 8.0));
    if (n == 0) return {1, 1, 1};
    const double at = t * 65535.0;
    if (at <= num("ctime0", 0)) return key(0);
    for (int i = 1; i < n; ++i) {
        const double t0 = num("ctime" + std::to_string(i - 1), 0),
                     t1 = num("ctime" + std::to_string(i), 65535);
        if (at > t1) continue;
        if (num("m_Mode", 0) == 1 || t1 <= t0) return key(i);  // fixed: the next key's colour
        const float w = float((at - t0) / (t1 - t0));
        const Rgb a = key(i - 1), b = key(i);
        return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
    }
    return key(n - 1);
}

//! flarekit's blend for Unity's blendMode integer in the given order; nullopt when unknown.
std::optional<BlendMode> blendOf(int mode, bool early) {
    // current: Additive, Screen, Premultiply, Lerp; early: Lerp, Additive, Premultiply, Screen.
    static constexpr BlendMode current[] = {BlendMode::Add, BlendMode::Screen, BlendMode::Over,
                                            BlendMode::Over};
    static constexpr BlendMode earlyOrder[] = {BlendMode::Over, BlendMode::Add, BlendMode::Over,
                                               BlendMode::Screen};
    if (mode < 0 || mode > 3) return std::nullopt;
    return early ? earlyOrder[mode] : current[mode];
}
int unityBlendOf(BlendMode b, bool early) {
    switch (b) {
        case BlendMode::Add:
            return early ? 1 : 0;
        case BlendMode::Screen:
            return early ? 3 : 1;
        default:
            return 2;  // Premultiply: flarekit's over is premultiplied
    }
}

Result<json> parseUnityYaml(const std::string& text, const std::string& path) {
    auto bodies = unityDocuments(text, path);
    if (!bodies) return bodies.error();
    try {
        for (const std::string& body : *bodies) {
            const YAML::Node doc = YAML::Load(body);
            if (!doc.IsMap() || !doc["MonoBehaviour"] || !doc["MonoBehaviour"]["elements"])
                continue;
            YamlBudget budget;
            json mono = yamlToJson(doc["MonoBehaviour"], budget);
            if (budget.exceeded)
                return invalidInput(path + ": MonoBehaviour: expected a lens-flare asset, got " +
                                    "more than a million YAML nodes or nesting deeper than 64");
            return mono;
        }
    } catch (const YAML::Exception& e) {
        return invalidInput(path + ": invalid YAML at line " + std::to_string(e.mark.line + 1) +
                            ": " + e.msg);
    }
    return invalidInput(path +
                        ": MonoBehaviour.elements: missing; expected a Unity Lens Flare (SRP) "
                        "data asset (LensFlareDataSRP)");
}

//! The GUID of a texture written beside the asset without a .meta of its own: the .meta
//! already beside the output when there is one (a project's references to that texture must
//! keep working, so it is never replaced), else a new one written with it.
std::string newTextureMeta(const std::string& file, ExportContext& ctx) {
    const fs::path existing = fs::path(ctx.path).parent_path() / (file + ".meta");
    if (std::string guid = unityGuidOfMeta(existing); !guid.empty()) return guid;
    const std::string guid = unityGuidFor(ctx.path, file);
    ctx.files.push_back({file + ".meta", {}, {}, unityTextureMeta(guid)});
    return guid;
}

}  // namespace

Result<FlareAsset> readUnity(const std::string& text, ImportContext& ctx) {
    auto parsed = parseUnityYaml(text, ctx.path);
    if (!parsed) return parsed.error();
    const json& mono = *parsed;
    const JsonPlace top(ctx.path, "MonoBehaviour");
    const json& elements = mono["elements"];
    if (!elements.is_array() || elements.empty() || elements.size() > kMaxPresetElements)
        return (top / "elements")
            .fail("expected a list of 1 to " + std::to_string(kMaxPresetElements) + " elements");
    const bool earlySchema = elements[0].contains("aspectRatio") && !elements[0].contains("sizeXY");
    const bool early = ctx.options.unityBlendOrder == UnityBlendOrder::Early ||
                       (ctx.options.unityBlendOrder == UnityBlendOrder::Auto && earlySchema);
    std::map<std::string, std::string> textures;
    bool texturesIndexed = false;
    FlareAsset asset;
    asset.sprite.name = fieldOr(mono, "m_Name", fs::path(ctx.path).stem().string());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const JsonPlace at = (top / "elements").index(i);
        if (!elements[i].is_object()) return at.fail("expected a map");
        const Fields f{elements[i], at};
        const std::string label = "elements[" + std::to_string(i) + "]";
        auto type = f.number({"flareType"}, 1);
        if (!type) return type.error();
        if (*type != std::floor(*type) || *type < 0 || *type > 4)
            return (at / "flareType")
                .fail(
                    "expected 0 (image), 1 (circle), 2 (polygon), 3 (ring) or 4 (nested "
                    "flare), got " +
                    jsonExcerpt(elements[i]["flareType"]));
        if (int(*type) == kNested) {
            ctx.warn(label +
                     ": a nested lens-flare asset is not drawn by flarekit; kept in "
                     "source");
        }
        auto position = f.number({"position"}, 0, -8, 8);
        auto scale = f.number({"uniformScale"}, 1, 0, 1e4);
        auto sx = f.component("sizeXY", "x", 1), sy = f.component("sizeXY", "y", 1);
        auto intensity = f.number({"m_LocalIntensity", "localIntensity"}, 1, 0, 1e6);
        auto rotation = f.number({"rotation"}, 0, -1e4, 1e4);
        auto visible = f.number({"visible"}, 1, 0, 1);
        auto blendMode = f.number({"blendMode"}, 0);
        auto edgeOffset = f.number({"m_EdgeOffset", "edgeOffset"}, 0.1, 0, 1);
        auto fallOff = f.number({"m_FallOff", "fallOff"}, 1, 0, 1);
        auto sides = f.number({"m_SideCount", "sideCount"}, 6, 3, 32);
        auto roundness = f.number({"m_SdfRoundness", "sdfRoundness"}, 0, 0, 1);
        auto multiple = f.number({"allowMultipleElement"}, 0, 0, 1);
        auto count = f.number({"m_Count", "count"}, 1, 1, double(kMaxPresetElements));
        auto distribution = f.number({"distribution"}, 0, 0, 2);
        auto spread = f.number({"lengthSpread"}, 1, -100, 100);
        auto angleStep = f.number({"uniformAngle"}, 0, -1e4, 1e4);
        auto thickness = f.number({"ringThickness"}, 0.25, 0, 1);
        auto tint = tintOf(f, at);
        if (auto err = firstError(position, scale, sx, sy, intensity, rotation, visible, blendMode,
                                  edgeOffset, fallOff, sides, roundness, multiple, count,
                                  distribution, spread, angleStep, thickness, tint))
            return *err;
        const auto blend = *blendMode == std::floor(*blendMode) && std::abs(*blendMode) < 1e6
                               ? blendOf(int(*blendMode), early)
                               : std::nullopt;
        if (!blend)
            return (at / "blendMode")
                .fail(std::string("expected 0 to 3 (") +
                      (early ? "early order: lerp, additive, premultiply, screen"
                             : "additive, screen, premultiply, lerp") +
                      "), got " + jsonExcerpt(elements[i]["blendMode"]));
        if (*sy <= 0 || *sx <= 0) return (at / "sizeXY").fail("expected x and y above 0");
        ElementParams e;
        switch (int(*type)) {
            case kImage: {
                const json* tex = f.find({"lensFlareTexture"});
                const std::string guid = tex ? fieldOr(*tex, "guid", std::string()) : std::string();
                if (guid.empty())
                    return (at / "lensFlareTexture")
                        .fail("expected {fileID, guid, type} of a texture for an image element");
                if (!texturesIndexed) {
                    textures =
                        indexUnityTextures(unityTextureRoots(ctx.dir, ctx.options.unityAssets));
                    texturesIndexed = true;
                }
                const auto found = textures.find(guid);
                if (found == textures.end())
                    return (at / "lensFlareTexture")
                        .fail("expected the texture of guid " + guid +
                              " (a .meta file naming it, under the asset's Assets folder or "
                              "--unity-assets), found none");
                e = defaultElement(ElementType::Image);
                if (Status s = loadTexture(ctx, found->second, at / "lensFlareTexture", e); !s)
                    return s.error();
                break;
            }
            case kPolygon:
                e = defaultElement(ElementType::Polygon);
                e.blades = int(*sides);
                e.softness = float(1.0 - *edgeOffset);
                e.roundness = float(*roundness);
                break;
            case kRing:
                e = defaultElement(ElementType::Ring);
                e.width = float(std::max(0.001, *thickness));
                break;
            default:  // circle, and the nested flare's placeholder
                e = defaultElement(ElementType::Disc);
                e.softness = float(1.0 - *edgeOffset);
                break;
        }
        if ((int(*type) == kCircle || int(*type) == kPolygon) && *fallOff != 1.0)
            ctx.warn(label + ".m_FallOff " + unityNumber(*fallOff) +
                     ": flarekit's edge eases linearly (Unity's fall-off 1); kept in source");
        e.innerColor.reset();
        e.color = *tint;
        e.intensity = float(*intensity);
        e.t = tFromU(2.0 * *position);
        e.size = float(kUnitySizeToRadius * *scale * *sy);
        e.aspect = float(std::clamp(*sx / *sy, 0.05, 20.0));
        e.rotationDeg = float(std::fmod(*rotation, 360.0));
        e.blend = *blend;
        e.visible = *visible != 0 && int(*type) != kNested;
        auto angular = f.number({"angularOffset"}, 0);
        if (angular && *angular != 0)
            ctx.warn(label +
                     ".angularOffset: flarekit keeps elements on the flare line; kept in "
                     "source");
        if (auto distortion = f.number({"enableRadialDistortion"}, 0);
            distortion && *distortion != 0)
            ctx.warn(label +
                     ".enableRadialDistortion: flarekit does not resize elements toward "
                     "the frame edge; kept in source");
        for (const char* k : {"positionOffset", "translationScale"}) {
            auto x = f.component(k, "x", k[0] == 'p' ? 0 : 1);
            auto y = f.component(k, "y", k[0] == 'p' ? 0 : 1);
            if (x && y && (*x != (k[0] == 'p' ? 0 : 1) || *y != (k[0] == 'p' ? 0 : 1)))
                ctx.warn(label + "." + k +
                         ": flarekit keeps elements on the flare line; kept "
                         "in source");
        }
        // Kept: everything but what flarekit now holds (written back from it), plus the blend
        // order and the keys that choose how it is written back (uniformScale, blendMode, tint's
        // alpha, flareType).
        json kept = unmappedFields(elements[i], {"position", "m_LocalIntensity", "localIntensity",
                                                 "rotation", "visible", "sizeXY"});
        if (int(*type) == kCircle || int(*type) == kPolygon)
            for (const char* k : {"m_EdgeOffset", "edgeOffset"}) kept.erase(k);
        if (int(*type) == kPolygon)
            for (const char* k : {"m_SideCount", "sideCount", "m_SdfRoundness", "sdfRoundness"})
                kept.erase(k);
        if (int(*type) == kRing) kept.erase("ringThickness");
        kept["blend_order"] = early ? "early" : "current";
        e.source = sourceBlock(FlareFormat::Unity, kept);
        const int copies = *multiple != 0 ? int(*count) : 1;
        if (copies > 1 && *distribution != 0)
            ctx.warn(label + ".distribution " +
                     (*distribution == 1 ? std::string("1 (curve)") : std::string("2 (random)")) +
                     ": flarekit draws the element once at its position; kept in source");
        const int n = *distribution == 0 ? copies : 1;
        if (asset.sprite.elements.size() + std::size_t(n) > kMaxPresetElements)
            return at.fail("expected at most " + std::to_string(kMaxPresetElements) +
                           " elements in all (counting m_Count copies)");
        for (int c = 0; c < n; ++c) {
            ElementParams copy = e;
            if (n > 1) {
                copy.t = tFromU(2.0 * *position + double(c) * 2.0 * *spread / (n - 1));
                copy.rotationDeg = float(std::fmod(*rotation + c * *angleStep, 360.0));
                // Each copy takes its colour from the element's gradient at i / (count - 1).
                const Rgb g = gradientAt(
                    elements[i].contains("colorGradient") ? elements[i]["colorGradient"] : json(),
                    double(c) / (n - 1));
                for (int ch = 0; ch < 3; ++ch) copy.color[std::size_t(ch)] *= g[std::size_t(ch)];
                if (c > 0) copy.source = json{{"format", "unity"}, {"copy", true}}.dump();
            }
            asset.sprite.elements.push_back(std::move(copy));
        }
    }
    json rest = mono;
    rest.erase("elements");
    asset.sprite.source = sourceBlock(FlareFormat::Unity, rest);
    return asset;
}

Result<std::string> writeUnity(const Preset& preset, ExportContext& ctx) {
    json mono = sourceFields(preset.source, FlareFormat::Unity);
    if (mono.empty()) {
        mono = json::parse(R"({"m_ObjectHideFlags": "0",
            "m_CorrespondingSourceObject": {"fileID": "0"}, "m_PrefabInstance": {"fileID": "0"},
            "m_PrefabAsset": {"fileID": "0"}, "m_GameObject": {"fileID": "0"},
            "m_Enabled": "1", "m_EditorHideFlags": "0"})");
        mono["m_Script"] = {{"fileID", "11500000"}, {"guid", kLensFlareScriptGuid}, {"type", "3"}};
        mono["m_EditorClassIdentifier"] = "";
    }
    mono["m_Name"] = preset.name;
    json elements = json::array();
    for (std::size_t i = 0; i < preset.elements.size(); ++i) {
        const ElementParams& e = preset.elements[i];
        const std::string label = elementLabel(e, i);
        json u = sourceFields(e.source, FlareFormat::Unity);
        if (isCountCopy(e)) continue;
        const bool early = fieldOr(u, "blend_order", std::string("current")) == "early";
        u.erase("blend_order");
        const auto set = [&](const char* key, double v) { u[key] = unityNumber(v); };
        // The names this element was read with (pre-12.0 assets lack the m_ prefix).
        const auto name = [&](const char* current, const char* old) {
            return u.contains(old) && !u.contains(current) ? old : current;
        };
        set("visible", e.visible ? 1 : 0);
        set("position", uFromT(e.t) / 2.0);
        double scale = 1;
        if (u.contains("uniformScale"))
            scale = std::atof(u["uniformScale"].get<std::string>().c_str());
        if (!(scale > 0)) scale = 1;
        double radius = e.size;
        int type = kCircle;
        switch (e.type) {
            case ElementType::Image: {
                type = kImage;
                // The texture keeps its GUID when it has a .meta (Unity keeps GUIDs when assets
                // move between projects with their .meta), so references to it still hold.
                const std::string file = ctx.addCopy(e.texture);
                std::string guid = unityGuidOfMeta(e.texture + ".meta");
                if (guid.empty()) {
                    guid = newTextureMeta(file, ctx);
                } else {
                    ctx.addCopy(e.texture + ".meta");
                }
                u["lensFlareTexture"] = {{"fileID", "2800000"}, {"guid", guid}, {"type", "3"}};
                break;
            }
            case ElementType::Polygon:
                type = kPolygon;
                set(name("m_SideCount", "sideCount"), e.blades);
                set(name("m_SdfRoundness", "sdfRoundness"), e.roundness);
                set(name("m_EdgeOffset", "edgeOffset"), 1.0 - e.softness);
                break;
            case ElementType::Disc:
                set(name("m_EdgeOffset", "edgeOffset"), 1.0 - e.softness);
                break;
            case ElementType::Ring:
                type = kRing;
                set("ringThickness", e.width);
                break;
            default: {
                // Glow, streaks, rays, edge streak: Unity has no such shape; baked.
                type = kImage;
                float share = 1.f, gain = 1.f;
                const std::string file = ctx.addBaked(e, int(i), share, gain);
                const std::string guid = newTextureMeta(file, ctx);
                u["lensFlareTexture"] = {{"fileID", "2800000"}, {"guid", guid}, {"type", "3"}};
                radius = e.size / share;
                set(name("m_LocalIntensity", "localIntensity"), gain);
                ctx.warn(label + "baked into a texture: Unity has no " +
                         std::string(elementTypeName(e.type)) + " shape");
                break;
            }
        }
        if (type == kCircle || type == kPolygon || type == kImage || type == kRing)
            set("flareType", type);
        if (type != kImage || e.type == ElementType::Image)
            set(name("m_LocalIntensity", "localIntensity"), e.intensity);
        set("uniformScale", scale);
        const double sy = radius / (kUnitySizeToRadius * scale);
        u["sizeXY"] = {{"x", unityNumber(sy * e.aspect)}, {"y", unityNumber(sy)}};
        set("rotation", e.rotationDeg);
        const bool baked = type == kImage && e.type != ElementType::Image;
        Rgb c = baked ? Rgb{1, 1, 1} : e.color;
        // The first of several uniform copies carries the gradient's first colour: the tint is
        // what remains (the copies were read as tint x gradient).
        if (fieldOr(u, "allowMultipleElement", std::string("0")) == "1" &&
            fieldOr(u, "distribution", std::string("0")) == "0" && u.contains("colorGradient")) {
            const Rgb g = gradientAt(u["colorGradient"], 0.0);
            for (int ch = 0; ch < 3; ++ch)
                c[std::size_t(ch)] = g[std::size_t(ch)] > 0.f
                                         ? c[std::size_t(ch)] / g[std::size_t(ch)]
                                         : c[std::size_t(ch)];
        }
        const std::string alpha = u.contains("tint") && u["tint"].is_object()
                                      ? fieldOr(u["tint"], "a", std::string("1"))
                                      : std::string("1");
        u["tint"] = {{"r", unityNumber(c[0])},
                     {"g", unityNumber(c[1])},
                     {"b", unityNumber(c[2])},
                     {"a", alpha}};
        // Keep the integer the asset had when it means the same blend (lerp and premultiply
        // both read as flarekit's over).
        const int had =
            u.contains("blendMode") ? std::atoi(u["blendMode"].get<std::string>().c_str()) : -1;
        if (blendOf(had, early) != e.blend) set("blendMode", unityBlendOf(e.blend, early));
        if (e.innerColor && e.type != ElementType::Image && !baked && *e.innerColor != e.color)
            ctx.warn(label + "inner_color: Unity's circles and polygons have one tint");
        if (e.type == ElementType::EdgeStreak)
            ctx.warn(label + "Unity places every element on the flare line, not on the frame edge");
        elements.push_back(std::move(u));
    }
    if (preset.intensity != 1.f)
        ctx.warn("intensity " + unityNumber(preset.intensity) +
                 ": a Unity flare's intensity is on its component, not its asset; not written");
    mono["elements"] = std::move(elements);
    YAML::Emitter out;
    out << YAML::BeginMap << YAML::Key << "MonoBehaviour" << YAML::Value;
    emitJson(out, mono);
    out << YAML::EndMap;
    if (!out.good()) return internalError(ctx.path + ": writing YAML: " + out.GetLastError());
    return std::string("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &11400000\n") +
           out.c_str() + "\n";
}

}  // namespace flarekit::convert
