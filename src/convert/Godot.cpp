// SPDX-License-Identifier: Apache-2.0
// Godot's lens-flare add-on (SIsilicon's "Lens Flare" plug-in for Godot 3 and 4, a screen-space
// flare after John Chapman's "Pseudo Lens Flare", 2013): its node's properties flareStrength,
// flareBias, flareBlur, distortion, distortionQuality, ghostCount, ghostSpacing, haloWidth,
// streakStrength and lensDirt, read from the node in a .tscn scene or from a JSON of them, to
// and from a flarekit post-process preset.
//
// The mapping (Chapman's shader, which the add-on runs): ghost i of a light at l (from the
// centre) lands at -l / (1 - i x spacing), flarekit's ghost series of start 1 and that spacing;
// the bias is subtracted from the scene (a hard threshold); the halo is a ring haloWidth of the
// texture (frame heights, vertically) from the centre, 2 x haloWidth half heights; the
// distortion offsets red and blue by that many texels of the add-on's 1/4-resolution buffer,
// about distortion / 240 of the distance to the centre at a 1920-wide frame's edge; the
// strength is scaled so the add-on's default (10) is flarekit's flare_intensity 1.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "convert/ConvertCommon.h"
#include "flarekit/ParamText.h"

namespace flarekit::convert {

namespace {

constexpr double kStrengthPerIntensity = 10.0;  //!< the add-on's default strength
constexpr double kTexelsPerAmount = 240.0;      //!< distortion texels per chromatic amount
//! Chapman's ghost weight (1 - |offset| / sqrt(0.5))^10 is flarekit's ghost falloff 10.
constexpr float kChapmanGhostFalloff = 10.f;

struct GodotKey {
    const char* name;
    double fallback, min, max;
};
//! The add-on's exported properties with their defaults and ranges (lens-flare.gd).
constexpr GodotKey kKeys[] = {
    {"flareStrength", 10, 0, 100}, {"flareBias", 1.05, 0, 16},    {"flareBlur", 2, 0, 10},
    {"distortion", 2, 0, 50},      {"ghostCount", 7, 0, 32},      {"ghostSpacing", 0.3, 0, 1},
    {"haloWidth", 0.25, 0, 1},     {"streakStrength", 0, 0, 100}, {"distortionQuality", 0, 0, 2},
};

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

bool isGodotKey(const std::string& k) {
    for (const GodotKey& g : kKeys)
        if (k == g.name) return true;
    return k == "lensDirt";
}

//! The properties of the node that carries the add-on's keys: `key = value` lines after its
//! [node ...] header, numbers as numbers and anything else (ExtResource( 2 )) as its text.
Result<json> parseTscn(const std::string& text, const std::string& path) {
    std::istringstream in(text);
    json node = json::object(), best = json::object(), resources = json::array();
    std::string header, bestHeader;
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        line = trim(line);
        if (line.empty() || line[0] == ';') continue;
        if (line.rfind("[ext_resource", 0) == 0) {
            resources.push_back(line);  // written back, so ExtResource( n ) still resolves
            continue;
        }
        if (line[0] == '[') {
            if (node.size() > best.size()) best = node, bestHeader = header;
            node = json::object();
            header = line;
            continue;
        }
        const auto eq = line.find('=');
        if (eq == std::string::npos) continue;  // a multi-line value's continuation
        const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
        if (!isGodotKey(key) && key != "script") continue;
        char* end = nullptr;
        const double x = std::strtod(value.c_str(), &end);
        if (isGodotKey(key) && key != "lensDirt" && (value.empty() || *end != '\0'))
            return invalidInput(path + ": line " + std::to_string(lineNo) + ": " + key +
                                ": expected a number, got '" + value.substr(0, 60) + "'");
        // Written without a point: an integer (ghostCount = 6), when it is one that fits.
        const bool whole = value.find_first_of(".eE") == std::string::npos && std::isfinite(x) &&
                           std::abs(x) < 1e15 && x == std::floor(x);
        node[key] = key == "lensDirt" || key == "script" ? json(value)
                    : whole                              ? json((long long)x)
                                                         : json(x);
    }
    if (node.size() > best.size()) best = node, bestHeader = header;
    if (best.empty() || (best.size() == 1 && best.contains("script")))
        return invalidInput(path +
                            ": expected a node with the Godot lens-flare add-on's "
                            "properties (flareStrength, ghostCount, ...), found none");
    best["node"] = bestHeader;
    best["ext_resources"] = resources;
    return best;
}

}  // namespace

Result<FlareAsset> readGodot(const std::string& text, ImportContext& ctx) {
    auto parsed = jsonOrText(text, ctx.path, parseTscn);
    if (!parsed) return parsed.error();
    json doc = *parsed;
    const JsonPlace top(ctx.path);
    std::map<std::string, double> v;
    for (const GodotKey& k : kKeys) {
        auto x = readNumber(doc, k.name, top, k.fallback, k.min, k.max);
        if (!x) return x.error();
        v[k.name] = *x;
    }
    if (v["ghostCount"] != std::floor(v["ghostCount"]))
        return (top / "ghostCount").fail("expected a whole number of ghosts");
    FlareAsset asset;
    asset.postFx = true;
    PostFxParams& p = asset.chain;
    p.name = fs::path(ctx.path).stem().string();
    p.flareIntensity = float(v["flareStrength"] / kStrengthPerIntensity);
    p.bright.threshold = float(v["flareBias"]);
    p.bright.knee = 0.f;
    p.bloom.intensity = 0.f;  // the add-on adds no bloom of its own
    for (int i = 0; i < int(v["ghostCount"]); ++i) {
        GhostParams g;
        g.scale = float(1.0 - double(i) * v["ghostSpacing"]);
        if (std::abs(g.scale) < kMinGhostScale) {
            ctx.warn("ghost " + std::to_string(i) + " of spacing " +
                     formatParamNumber(v["ghostSpacing"]) +
                     ": it would sit at infinity (scale 0); left out");
            continue;
        }
        g.blur = float(v["flareBlur"]);
        g.falloff = kChapmanGhostFalloff;
        g.threshold = 0.f;
        g.centered = true;
        g.linearFilter = true;
        g.saturation = 1.f;
        p.ghosts.push_back(g);
    }
    if (v["haloWidth"] > 0) {
        p.halo.intensity = 1.f;
        p.halo.radius = float(2.0 * v["haloWidth"]);
        p.halo.threshold = 0.f;
    }
    p.chromatic.amount = float(std::min(0.5, v["distortion"] / kTexelsPerAmount));
    p.streaks.intensity = float(v["streakStrength"]);
    if (doc.contains("lensDirt"))
        ctx.warn("lensDirt: flarekit's dirt is procedural, not a texture; kept in source");
    if (v["distortionQuality"] != 0)
        ctx.warn(
            "distortionQuality: flarekit samples the chromatic fringe one way; kept in "
            "source");
    json kept = json::object();
    for (const auto& [k, x] : doc.items()) {
        if (k == "lensDirt" || k == "script" || k == "node" || k == "ext_resources" ||
            k == "distortionQuality" || !isGodotKey(k))
            kept[k] = x;
    }
    // Values that map only approximately are kept too, so that converting back is exact.
    kept["distortion"] = v["distortion"];
    kept["haloWidth"] = v["haloWidth"];
    p.source = sourceBlock(FlareFormat::Godot, kept);
    if (Status s = validatePostFxParams(p); !s)
        return invalidInput(ctx.path + ": " + s.error().message);
    return asset;
}

Result<std::string> writeGodot(const PostFxParams& p, ExportContext& ctx) {
    const json kept = sourceFields(p.source, FlareFormat::Godot);
    json out = json::object();
    out["flareStrength"] = double(p.flareIntensity) * kStrengthPerIntensity;
    out["flareBias"] = p.bright.threshold;
    const std::size_t n = p.ghosts.size();
    double spacing = kKeys[5].fallback;
    if (n >= 2) spacing = double(p.ghosts[0].scale) - double(p.ghosts[1].scale);
    bool series = n == 0 || p.ghosts[0].scale == 1.f;
    for (std::size_t i = 0; i < n && series; ++i)
        series = std::abs(double(p.ghosts[i].scale) - (1.0 - double(i) * spacing)) < 1e-4;
    if (!series)
        ctx.warn("ghosts: the add-on draws an evenly spaced series from scale 1; written as " +
                 std::to_string(n) + " ghosts of spacing " + formatParamNumber(spacing));
    out["ghostCount"] = n;
    out["ghostSpacing"] = spacing;
    out["flareBlur"] = n ? p.ghosts[0].blur : 0.f;
    // Round trip: the source's own values where flarekit's still match what they were read as.
    const double halo = p.halo.intensity > 0 ? double(p.halo.radius) / 2.0 : 0.0;
    const double keptHalo = fieldOr(kept, "haloWidth", -1.0);
    out["haloWidth"] = std::abs(keptHalo - halo) < 1e-6 ? keptHalo : halo;
    const double keptDistortion = fieldOr(kept, "distortion", -1.0);
    out["distortion"] =
        keptDistortion >= 0 && std::abs(std::min(0.5, keptDistortion / kTexelsPerAmount) -
                                        double(p.chromatic.amount)) < 1e-6
            ? keptDistortion
            : double(p.chromatic.amount) * kTexelsPerAmount;
    if (p.streaks.intensity > 0) out["streakStrength"] = p.streaks.intensity;
    for (const auto& [k, x] : kept.items())
        if (!out.contains(k) && k != "node" && k != "script" && k != "ext_resources") out[k] = x;
    // The add-on's own ranges (its inspector clamps to them): a value past one is written at
    // the bound, with a warning.
    for (const GodotKey& k : kKeys) {
        if (!out.contains(k.name) || !out[k.name].is_number()) continue;
        const double x = out[k.name].get<double>(), c = std::clamp(x, k.min, k.max);
        if (c == x) continue;
        ctx.warn(std::string(k.name) + " " + formatParamNumber(x) + ": past the add-on's range " +
                 formatParamRange(k.min, k.max) + "; written as " + formatParamNumber(c));
        out[k.name] = c;
    }
    const auto dropped = [&](bool on, const char* what) {
        if (on) ctx.warn(std::string(what) + ": the Godot add-on has none; left out");
    };
    dropped(p.bloom.intensity > 0, "bloom");
    dropped(p.starburst.intensity > 0, "starburst");
    dropped(p.dirt.intensity > 0, "dirt (procedural)");
    for (auto& [k, x] : out.items())
        if (x.is_number_float()) x = tidy(x.get<double>());
    if (fs::path(ctx.path).extension() == ".json") return out.dump(2) + "\n";
    // A scene holding the add-on's node, as Godot writes one (format 2: Godot 3).
    const std::string script = fieldOr(kept, "script", std::string("ExtResource( 1 )"));
    std::ostringstream os;
    os.precision(9);
    json resources = fieldOr(kept, "ext_resources", json::array());
    if (resources.empty())
        resources.push_back(
            "[ext_resource path=\"res://addons/lens-flare/lens-flare.gd\" type=\"Script\" id=1]");
    os << "[gd_scene load_steps=" << resources.size() + 1 << " format=2]\n\n";
    for (const json& r : resources) os << r.get<std::string>() << "\n";
    // The add-on's node as it was; one that had a parent gets a plain root to hang from.
    const std::string node =
        fieldOr(kept, "node", std::string("[node name=\"LensFlare\" type=\"Node\"]"));
    if (node.find(" parent=") != std::string::npos) os << "\n[node name=\"Root\" type=\"Node\"]\n";
    os << "\n"
       << node << "\n"
       << "script = " << script << "\n";
    for (const auto& [k, x] : out.items())
        os << k << " = " << (x.is_string() ? x.get<std::string>() : x.dump()) << "\n";
    return os.str();
}

}  // namespace flarekit::convert
