// SPDX-License-Identifier: Apache-2.0
// Unreal Engine's post-process lens flare (FPostProcessSettings: LensFlareIntensity,
// LensFlareTint, LensFlareBokehSize, LensFlareThreshold, LensFlareTints[8]) to and from a
// flarekit post-process preset. Unreal draws 8 flares, each the thresholded scene scaled about
// the view centre by -A (the alpha of LensFlareTints[i], "its position"), tinted by its RGB and
// by LensFlareTint: a light at l (from the centre) gives flare i at -A l, which is flarekit's
// ghost of scale 1 / A (a light at l gives a ghost at -l / scale).
//
// Read from the JSON FJsonObjectConverter writes (keys in any case) or from the text Unreal
// copies and its .ini files hold: `Key=Value` lines, or one `(Key=Value,...)` struct, colours as
// (R=..,G=..,B=..,A=..).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "convert/ConvertCommon.h"
#include "flarekit/ParamText.h"

namespace flarekit::convert {

namespace {

//! Unreal's defaults (Scene.h): intensity 1, threshold 8, bokeh size 3, and the eight tints.
constexpr double kDefaultThreshold = 8.0;
constexpr double kDefaultBokehSize = 3.0;
constexpr int kUnrealFlares = 8;
//! flarekit's |scale| range (kMinGhostScale to 16) as Unreal positions A = 1 / scale.
constexpr double kMaxPosition = 1.0 / kMinGhostScale, kMinPosition = 1.0 / 16.0;
//! Where flarekit draws a flare of position `a`: `a` itself within its ghost scales, else the
//! nearest end on the same side (A = 0, on the centre, counts as positive).
double drawnPosition(double a) {
    return std::copysign(std::clamp(std::abs(a), kMinPosition, kMaxPosition), a == 0 ? 1.0 : a);
}
//! The source block's key for the .ini section the settings were read under.
constexpr const char* kSectionKey = "__section";
//! The section an exported .ini is written under when the source had none: where a project's
//! DefaultEngine.ini or a copied PostProcessSettings block keeps these keys.
constexpr const char* kDefaultSection = "[/Script/Engine.PostProcessSettings]";
//! The source block's key for the positions A outside that range, by flare index.
constexpr const char* kClampedPositions = "__clamped_positions";

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower((unsigned char)c));
    return s;
}
std::string ext(const std::string& path) {
    return lower(fs::path(path).extension().string());
}
std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

//! Splits "a=1,b=(c=2,d=3)" at top-level commas.
std::vector<std::string> splitTopLevel(const std::string& s, char sep) {
    std::vector<std::string> parts;
    int depth = 0;
    std::string cur;
    for (char c : s) {
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if (c == sep && depth == 0) {
            parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!trim(cur).empty()) parts.push_back(cur);
    return parts;
}

//! One Unreal text value as JSON: a number, a bool, a struct (R=..,G=..) or a string.
json textValue(const std::string& raw) {
    const std::string v = trim(raw);
    if (v.size() >= 2 && v.front() == '(' && v.back() == ')') {
        json o = json::object();
        for (const std::string& part : splitTopLevel(v.substr(1, v.size() - 2), ',')) {
            const auto eq = part.find('=');
            if (eq == std::string::npos) return v;
            o[trim(part.substr(0, eq))] = textValue(part.substr(eq + 1));
        }
        return o;
    }
    if (lower(v) == "true" || lower(v) == "false") return lower(v) == "true";
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (!v.empty() && *end == '\0') return x;
    if (v.size() >= 2 && v.front() == '"' && v.back() == '"') return v.substr(1, v.size() - 2);
    return v;
}

//! The settings as one JSON object keyed as Unreal names them ("LensFlareTints[3]" kept as is).
Result<json> parseUnrealText(const std::string& text, const std::string& path) {
    json out = json::object();
    std::string body = trim(text);
    std::vector<std::string> items;
    if (!body.empty() && body.front() == '(' && body.back() == ')') {
        items = splitTopLevel(body.substr(1, body.size() - 2), ',');
    } else {
        std::istringstream in(body);
        for (std::string line; std::getline(in, line);) {
            line = trim(line);
            // The .ini section is kept (for the way back), as the first one seen.
            if (line.size() > 1 && line.front() == '[' && line.back() == ']' &&
                !out.contains(kSectionKey))
                out[kSectionKey] = line;
            if (line.empty() || line[0] == ';' || line[0] == '#' || line[0] == '[') continue;
            items.push_back(line);
        }
    }
    int lineNo = 0;
    for (const std::string& item : items) {
        ++lineNo;
        const auto eq = item.find('=');
        if (eq == std::string::npos)
            return invalidInput(path + ": item " + std::to_string(lineNo) +
                                ": expected Key=Value, got '" + trim(item).substr(0, 60) + "'");
        out[trim(item.substr(0, eq))] = textValue(item.substr(eq + 1));
    }
    return out;
}

//! The key of `doc` matching `name` case-insensitively (FJsonObjectConverter lower-cases the
//! first letter), or nullptr.
const json* findKey(const json& doc, const std::string& name, std::string* found = nullptr) {
    for (const auto& [k, v] : doc.items()) {
        if (lower(k) == lower(name)) {
            if (found) *found = k;
            return &v;
        }
    }
    return nullptr;
}

Result<double> unrealNumber(const json& doc, const std::string& key, const JsonPlace& at,
                            double fallback, double min, double max) {
    const json* v = findKey(doc, key);
    if (!v) return fallback;
    if (!v->is_number() || v->get<double>() < min || v->get<double>() > max)
        return (at / key).fail("expected a number in [" + std::to_string(int(min)) + ", " +
                               std::to_string(int(max)) + "], got " + jsonExcerpt(*v));
    return v->get<double>();
}

//! (R=,G=,B=,A=): the colour and its alpha.
Result<Rgb> unrealColor(const json& v, const JsonPlace& at, double& alpha) {
    std::optional<float> a;
    auto c = readRgb(v, at, &a);
    if (!c) return c.error();
    alpha = a.value_or(1.f);
    return c;
}

}  // namespace

Result<FlareAsset> readUnreal(const std::string& text, ImportContext& ctx) {
    auto parsed = jsonOrText(text, ctx.path, parseUnrealText);
    if (!parsed) return parsed.error();
    json doc = *parsed;
    // FPostProcessSettings exported whole nests the flare keys in "settings" at most.
    if (const json* inner = findKey(doc, "Settings"); inner && inner->is_object()) doc = *inner;
    const JsonPlace top(ctx.path);
    if (!findKey(doc, "LensFlareIntensity") && !findKey(doc, "LensFlareTints") &&
        !findKey(doc, "LensFlareTints[0]") && !findKey(doc, "LensFlareThreshold"))
        return top.fail(
            "expected Unreal post-process lens-flare settings (LensFlareIntensity, "
            "LensFlareTints, ...), found none");
    auto intensity = unrealNumber(doc, "LensFlareIntensity", top, 1.0, 0, 1000);
    auto threshold = unrealNumber(doc, "LensFlareThreshold", top, kDefaultThreshold, 0, 1e4);
    auto bokeh = unrealNumber(doc, "LensFlareBokehSize", top, kDefaultBokehSize, 0, 100);
    if (!intensity) return intensity.error();
    if (!threshold) return threshold.error();
    if (!bokeh) return bokeh.error();
    Rgb tint{1, 1, 1};
    double tintAlpha = 1;
    if (const json* v = findKey(doc, "LensFlareTint")) {
        auto c = unrealColor(*v, top / "LensFlareTint", tintAlpha);
        if (!c) return c.error();
        tint = *c;
    }
    // The eight tints: an array, or keys LensFlareTints[i]; Unreal's defaults where absent.
    static const double kDefaults[kUnrealFlares][4] = {
        {1.0, 0.8, 0.4, 0.6},  {1.0, 1.0, 0.6, 0.53}, {0.8, 0.8, 1.0, 0.46}, {0.5, 1.0, 0.4, 0.39},
        {0.5, 0.8, 1.0, 0.31}, {0.9, 1.0, 0.8, 0.27}, {1.0, 0.8, 0.4, 0.22}, {0.9, 0.7, 0.7, 0.15}};
    const json* array = findKey(doc, "LensFlareTints");
    if (array && (!array->is_array() || array->size() > kUnrealFlares))
        return (top / "LensFlareTints").fail("expected an array of at most 8 colours");
    FlareAsset asset;
    asset.postFx = true;
    PostFxParams& p = asset.chain;
    p.name = fs::path(ctx.path).stem().string();
    p.flareIntensity = float(*intensity);
    p.bright.threshold = float(*threshold);
    p.bright.knee = 0.f;      // Unreal subtracts the threshold: no soft knee
    p.bloom.intensity = 0.f;  // Unreal's bloom has its own settings; the flare is ghosts only
    json clampedPositions = json::object();  //!< flare index -> its own A, where clamped
    for (int i = 0; i < kUnrealFlares; ++i) {
        const std::string key = "LensFlareTints[" + std::to_string(i) + "]";
        const json* v =
            array && std::size_t(i) < array->size() ? &(*array)[std::size_t(i)] : findKey(doc, key);
        double a = kDefaults[i][3];
        Rgb c{float(kDefaults[i][0]), float(kDefaults[i][1]), float(kDefaults[i][2])};
        if (v) {
            auto rgb = unrealColor(
                *v, array ? (top / "LensFlareTints").index(std::size_t(i)) : top / key, a);
            if (!rgb) return rgb.error();
            c = *rgb;
        }
        // A flare nearer the centre than flarekit's largest ghost scale (A = 0 is on the centre)
        // or beyond its smallest is drawn at the nearest position flarekit has, and its own
        // position is kept for the way back.
        const double drawnAt = drawnPosition(a);
        if (drawnAt != a) {
            ctx.warn(key + ".A " + formatParamNumber(a) +
                     ": flarekit's ghosts lie at |A| from 0.0625 to 20 (scale 16 to 0.05); drawn "
                     "at " +
                     formatParamNumber(drawnAt) + ", kept in source");
            clampedPositions[std::to_string(i)] = a;
        }
        GhostParams g;
        g.tint = {c[0] * tint[0], c[1] * tint[1], c[2] * tint[2]};
        g.scale = float(1.0 / drawnAt);
        g.threshold = 0.f;
        g.saturation = 1.f;  // Unreal's tints are the flare's colour as given
        g.conserveArea = false;
        g.linearFilter = true;
        g.centered = true;
        p.ghosts.push_back(g);
    }
    std::string spelled;
    json kept = json::object();
    for (const auto& [k, v] : doc.items()) {
        const std::string l = lower(k);
        if (l != "lensflareintensity" && l != "lensflarethreshold" && l != "lensflaretints" &&
            l.rfind("lensflaretints[", 0) != 0)
            kept[k] = v;
    }
    if (*bokeh != kDefaultBokehSize || findKey(doc, "LensFlareBokehSize"))
        ctx.warn("LensFlareBokehSize " + formatParamNumber(*bokeh) +
                 ": flarekit's ghosts are not blurred by a bokeh of a share of the view; kept "
                 "in source");
    if (findKey(doc, "LensFlareBokehShape"))
        ctx.warn("LensFlareBokehShape: flarekit has no bokeh texture; kept in source");
    if (!clampedPositions.empty()) kept[kClampedPositions] = clampedPositions;
    // FJsonObjectConverter's lower camel case ("lensFlareIntensity") is written back as read.
    if (findKey(doc, "LensFlareIntensity", &spelled) && spelled[0] == 'l')
        kept["__key_case"] = "lower";
    p.source = sourceBlock(FlareFormat::Unreal, kept);
    if (Status s = validatePostFxParams(p); !s)
        return invalidInput(ctx.path + ": " + s.error().message);
    return asset;
}

Result<std::string> writeUnreal(const PostFxParams& p, ExportContext& ctx) {
    json kept = sourceFields(p.source, FlareFormat::Unreal);
    Rgb tint{1, 1, 1};
    if (const json* v = findKey(kept, "LensFlareTint")) {
        double a = 1;
        if (auto c = unrealColor(*v, JsonPlace(ctx.path, "source.LensFlareTint"), a)) tint = *c;
    }
    const auto divide = [](float x, float by) { return by > 0.f ? x / by : 0.f; };
    std::string section = ext(ctx.path) == ".ini" ? kDefaultSection : "";
    if (auto it = kept.find(kSectionKey); it != kept.end()) {
        if (it->is_string()) section = it->get<std::string>();
        kept.erase(it);
    }
    json clamped = json::object();
    if (auto it = kept.find(kClampedPositions); it != kept.end()) {
        if (it->is_object()) clamped = *it;
        kept.erase(it);
    }
    json out = json::object();
    out["LensFlareIntensity"] = p.flareIntensity;
    out["LensFlareThreshold"] = p.bright.threshold;
    json tints = json::array();
    for (int i = 0; i < kUnrealFlares; ++i) {
        if (std::size_t(i) >= p.ghosts.size()) {  // Unreal draws eight: the rest black
            tints.push_back({{"R", 0}, {"G", 0}, {"B", 0}, {"A", 0.5}});
            continue;
        }
        const GhostParams& g = p.ghosts[std::size_t(i)];
        double a = tidy(1.0 / double(g.scale));
        // A position the import clamped comes back as it was, unless the ghost was moved since.
        if (const json* own =
                clamped.contains(std::to_string(i)) ? &clamped[std::to_string(i)] : nullptr;
            own && own->is_number()) {
            const double original = own->get<double>();
            const double drawnAt = drawnPosition(original);
            if (std::abs(1.0 / double(g.scale) - drawnAt) <= 1e-6 * std::abs(drawnAt)) a = original;
        }
        tints.push_back({{"R", divide(g.tint[0], tint[0])},
                         {"G", divide(g.tint[1], tint[1])},
                         {"B", divide(g.tint[2], tint[2])},
                         {"A", a}});
    }
    if (p.ghosts.size() > std::size_t(kUnrealFlares))
        ctx.warn("ghosts " + std::to_string(p.ghosts.size()) +
                 ": Unreal draws 8 lens flares; the rest left out");
    if (p.bright.exposureRelative)
        ctx.warn("bright.exposure_relative: Unreal's threshold is absolute; written as is");
    const PostFxParams none;
    const auto dropped = [&](bool on, const char* what) {
        if (on) ctx.warn(std::string(what) + ": Unreal's lens flare has none; left out");
    };
    dropped(p.halo.intensity > 0, "halo");
    dropped(p.streaks.intensity > 0, "streaks");
    dropped(p.chromatic.amount > 0, "chromatic");
    dropped(p.starburst.intensity > 0, "starburst");
    dropped(p.dirt.intensity > 0, "dirt");
    dropped(p.bloom.intensity > 0, "bloom (Unreal's bloom settings are not the lens flare's)");
    const bool lowerCase = fieldOr(kept, "__key_case", std::string()) == "lower";
    kept.erase("__key_case");
    for (const auto& [k, v] : kept.items()) {
        // The source's own spelling of a key flarekit writes replaces flarekit's.
        std::string mine;
        if (findKey(out, k, &mine)) out.erase(mine);
        out[k] = v;
    }
    out = tidied(out);
    tints = tidied(tints);
    if (lowerCase) {
        json relabelled = json::object();
        for (auto& [k, v] : out.items()) {
            std::string key = k;
            if (key.rfind("LensFlare", 0) == 0) key[0] = 'l';
            relabelled[key] = v;
        }
        out = relabelled;
        for (json& c : tints) {
            json l = json::object();
            for (auto& [k, v] : c.items()) l[lower(k)] = v;
            c = l;
        }
    }
    const std::string tintsKey = lowerCase ? "lensFlareTints" : "LensFlareTints";
    out[tintsKey] = tints;
    if (ext(ctx.path) == ".json") return dumpByLine(out, tintsKey.c_str());
    // Text: one Key=Value per line under the section read (an .ini: Unreal's by default).
    std::ostringstream os;
    os.precision(9);
    if (!section.empty()) os << section << "\n";
    const auto value = [&](const json& v) -> std::string {
        if (v.is_object()) {
            std::string s = "(";
            for (const auto& [k, x] : v.items())
                s += (s.size() > 1 ? "," : "") + k + "=" +
                     (x.is_string() ? x.get<std::string>() : x.dump());
            return s + ")";
        }
        if (v.is_boolean()) return v.get<bool>() ? "True" : "False";
        return v.is_string() ? v.get<std::string>() : v.dump();
    };
    for (const auto& [k, v] : out.items()) {
        if (k == tintsKey) continue;
        os << k << "=" << value(v) << "\n";
    }
    for (std::size_t i = 0; i < tints.size(); ++i) {
        const json& c = tints[i];
        const auto at = [&](const char* k) { return (*findKey(c, k)).dump(); };
        os << "LensFlareTints[" << i << "]=(R=" << at("R") << ",G=" << at("G") << ",B=" << at("B")
           << ",A=" << at("A") << ")\n";
    }
    (void)none;
    return os.str();
}

}  // namespace flarekit::convert
