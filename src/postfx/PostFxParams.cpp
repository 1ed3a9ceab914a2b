// The one description of every post-process preset key: section, key, kind, range, unit and
// meaning (style.md habit 2). parsePostFxPreset validates against it, reports unknown keys
// with the list of known ones, and postFxParameterReference prints it for docs/postfx.md.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/JsonText.h"
#include "flare/PresetFiles.h"
#include "flarekit/Flare.h"
#include "flarekit/PostFx.h"

namespace flarekit {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

enum class Kind { Number, Integer, Seed, Color, Bool, Filter, Tone };

struct Field {
    std::string_view section;  //!< "" top level, "ghost" for ghosts[i] and ghost_series
    std::string_view key;
    Kind kind;
    double min, max;
    void* (*locate)(void* owner);  //!< owner: PostFxParams*, or GhostParams* for "ghost"
    std::string_view unit;
    std::string_view doc;
};

template <auto Section, auto Member>
void* in(void* p) { return &((static_cast<PostFxParams*>(p)->*Section).*Member); }
template <auto Member>
void* top(void* p) { return &(static_cast<PostFxParams*>(p)->*Member); }
template <auto Member>
void* ghost(void* p) { return &(static_cast<GhostParams*>(p)->*Member); }

using P = PostFxParams;
constexpr double kBig = 1e4;      //!< "any sensible HDR value": 10^4 x diffuse white
constexpr double kSeedMax = 2147483647.0;

// clang-format off
const Field kFields[] = {
    {"", "flare_intensity", Kind::Number, 0, 1000, top<&P::flareIntensity>, "", "multiplies ghosts, halo and streaks"},
    {"bright", "threshold", Kind::Number, 0, kBig, in<&P::bright, &BrightParams::threshold>, "linear", "bright-pass threshold: where the flare starts"},
    {"bright", "knee", Kind::Number, 0, kBig, in<&P::bright, &BrightParams::knee>, "linear", "soft knee half width: quadratic ease-in over [threshold - knee, threshold + knee]"},
    {"bloom", "intensity", Kind::Number, 0, 100, in<&P::bloom, &BloomParams::intensity>, "", "bloom added to the image (0: ghosts only)"},
    {"bloom", "levels", Kind::Integer, 2, 12, in<&P::bloom, &BloomParams::levels>, "mips", "downsample levels, 1/2 .. 1/2^levels: the bloom's reach"},
    {"bloom", "spread", Kind::Number, 0, 1, in<&P::bloom, &BloomParams::spread>, "", "weight of each coarser level in the upsample (1: mean of all levels)"},
    {"ghost", "tint", Kind::Color, 0, 100, ghost<&GhostParams::tint>, "linear RGB", "the seed's vTint"},
    {"ghost", "scale", Kind::Number, -16, 16, ghost<&GhostParams::scale>, "", "the seed's fTexScale: a light at l gives a ghost at -l / scale (|scale| >= 0.05)"},
    {"ghost", "blur", Kind::Number, 0, 16, ghost<&GhostParams::blur>, "bloom texels", "the seed's fBlurScale: sample step along the ray is blur x samples bloom texels"},
    {"ghost", "samples", Kind::Integer, 1, 64, ghost<&GhostParams::samples>, "", "the seed's NumSamples"},
    {"ghost", "threshold", Kind::Number, 0, kBig, ghost<&GhostParams::threshold>, "linear", "the seed's fThreshold, subtracted from every bloom sample"},
    {"ghost", "falloff", Kind::Number, 0, 64, ghost<&GhostParams::falloff>, "", "0: none (seed); else (1 - |n|/sqrt 2)^falloff of the unblurred point n (Chapman)"},
    {"ghost", "centered", Kind::Bool, 0, 1, ghost<&GhostParams::centered>, "", "false: the seed's sample offsets 1, -1, -3, ...; true: symmetric about the point"},
    {"ghost", "filter", Kind::Filter, 0, 1, ghost<&GhostParams::linearFilter>, "", "\"point\" (the seed's PointSampler) or \"bilinear\""},
    {"halo", "intensity", Kind::Number, 0, 100, in<&P::halo, &HaloParams::intensity>, "", "0 switches the halo off"},
    {"halo", "radius", Kind::Number, 0, 4, in<&P::halo, &HaloParams::radius>, "half heights", "ring radius about the centre (aspect-correct)"},
    {"halo", "thickness", Kind::Number, 0, 2, in<&P::halo, &HaloParams::thickness>, "half heights", "radial spread of the ring"},
    {"halo", "threshold", Kind::Number, 0, kBig, in<&P::halo, &HaloParams::threshold>, "linear", "subtracted from every bloom sample"},
    {"halo", "falloff", Kind::Number, 0, 64, in<&P::halo, &HaloParams::falloff>, "", "(1 - |p|/sqrt 2)^falloff of the ring's mid-radius sample point (Chapman uses 5)"},
    {"halo", "tint", Kind::Color, 0, 100, in<&P::halo, &HaloParams::tint>, "linear RGB", "ring colour"},
    {"streaks", "intensity", Kind::Number, 0, 100, in<&P::streaks, &StreakParams::intensity>, "", "0 switches the anamorphic streaks off"},
    {"streaks", "length", Kind::Number, 0, 2, in<&P::streaks, &StreakParams::length>, "image widths", "half length of a streak"},
    {"streaks", "falloff", Kind::Number, 0, 64, in<&P::streaks, &StreakParams::falloff>, "", "e^(-falloff t) along the streak, t = distance / length"},
    {"streaks", "threshold", Kind::Number, 0, kBig, in<&P::streaks, &StreakParams::threshold>, "linear", "subtracted from the bright image first"},
    {"streaks", "tint", Kind::Color, 0, 100, in<&P::streaks, &StreakParams::tint>, "linear RGB", "streak colour (anamorphic lenses: blue)"},
    {"chromatic", "amount", Kind::Number, 0, 0.5, in<&P::chromatic, &ChromaticParams::amount>, "", "red at (1 + amount), blue at (1 - amount) times the distance from the centre"},
    {"starburst", "intensity", Kind::Number, 0, 1, in<&P::starburst, &StarburstParams::intensity>, "", "0 off, 1 full modulation of ghosts and halo"},
    {"starburst", "spokes", Kind::Integer, 2, 64, in<&P::starburst, &StarburstParams::spokes>, "", "number of rays"},
    {"starburst", "width", Kind::Number, 0.01, 1, in<&P::starburst, &StarburstParams::width>, "spoke spacings", "ray half width"},
    {"starburst", "seed", Kind::Seed, 0, kSeedMax, in<&P::starburst, &StarburstParams::seed>, "", "per-ray random brightness"},
    {"dirt", "intensity", Kind::Number, 0, 100, in<&P::dirt, &DirtParams::intensity>, "", "0 off; bloom and flare x (1 + intensity x dirt)"},
    {"dirt", "spots", Kind::Integer, 0, 4096, in<&P::dirt, &DirtParams::spots>, "", "dust specks (plus one smudge per ten)"},
    {"dirt", "seed", Kind::Seed, 0, kSeedMax, in<&P::dirt, &DirtParams::seed>, "", "placement of the specks"},
    {"tonemap", "operator", Kind::Tone, 0, 1, in<&P::tone, &ToneParams::op>, "", "\"none\", \"aces\" (Narkowicz fit) or \"filmic\" (Hable)"},
    {"tonemap", "exposure", Kind::Number, 0, 1000, in<&P::tone, &ToneParams::exposure>, "", "multiplies the image before the curve"},
};
// clang-format on

//! ghost_series keys on top of the ghost ones.
constexpr std::string_view kSeriesKeys = "count, spacing, start, tints";
constexpr double kMinGhostScale = 0.05;  //!< below it a ghost magnifies one bloom texel over the frame

std::string range(double lo, double hi) {
    std::ostringstream os;
    os << "[" << lo << ", " << hi << "]";
    return os.str();
}

class Checker {
public:
    explicit Checker(std::string source) : m_source(std::move(source)) {}
    Error fail(const std::string& field, const std::string& what) const {
        return invalidInput(m_source + ": " + field + ": " + what);
    }

    std::optional<Error> number(const json& v, const std::string& at, double lo, double hi, double& out, bool integer) const {
        const bool isNumber = v.is_number() && std::isfinite(v.get<double>());
        const bool ok = isNumber && v.get<double>() >= lo && v.get<double>() <= hi &&
                        (!integer || v.get<double>() == std::floor(v.get<double>()));
        if (!ok) return fail(at, std::string("expected ") + (integer ? "an integer" : "a number") + " in " + range(lo, hi) + ", got " + jsonExcerpt(v));
        out = v.get<double>();
        return std::nullopt;
    }

    std::optional<Error> color(const json& v, const std::string& at, double lo, double hi, Rgb& out) const {
        const auto bad = [&] { return fail(at, "expected an array of 3 numbers in " + range(lo, hi) + ", got " + jsonExcerpt(v)); };
        if (!v.is_array() || v.size() != 3) return bad();
        for (std::size_t c = 0; c < 3; ++c) {
            double x = 0;
            if (number(v[c], at, lo, hi, x, false)) return bad();
            out[c] = float(x);
        }
        return std::nullopt;
    }

    std::optional<Error> assign(const Field& f, const json& v, const std::string& at, void* owner) const {
        void* ptr = f.locate(owner);
        double x = 0;
        switch (f.kind) {
            case Kind::Number:
                if (auto e = number(v, at, f.min, f.max, x, false)) return e;
                *static_cast<float*>(ptr) = float(x);
                return std::nullopt;
            case Kind::Integer:
                if (auto e = number(v, at, f.min, f.max, x, true)) return e;
                *static_cast<int*>(ptr) = int(x);
                return std::nullopt;
            case Kind::Seed:
                if (auto e = number(v, at, f.min, f.max, x, true)) return e;
                *static_cast<std::uint32_t*>(ptr) = std::uint32_t(x);
                return std::nullopt;
            case Kind::Color:
                return color(v, at, f.min, f.max, *static_cast<Rgb*>(ptr));
            case Kind::Bool:
                if (!v.is_boolean()) return fail(at, "expected true or false, got " + jsonExcerpt(v));
                *static_cast<bool*>(ptr) = v.get<bool>();
                return std::nullopt;
            case Kind::Filter:
                if (v != "point" && v != "bilinear") return fail(at, "expected \"point\" or \"bilinear\", got " + jsonExcerpt(v));
                *static_cast<bool*>(ptr) = v == "bilinear";
                return std::nullopt;
            case Kind::Tone: {
                auto& op = *static_cast<ToneOperator*>(ptr);
                if (v == "none") op = ToneOperator::None;
                else if (v == "aces") op = ToneOperator::Aces;
                else if (v == "filmic") op = ToneOperator::Filmic;
                else return fail(at, "expected \"none\", \"aces\" or \"filmic\", got " + jsonExcerpt(v));
                return std::nullopt;
            }
        }
        return std::nullopt;
    }

    //! Every key of object `v` into section `section` of `owner`; `extra` keys are left to the caller.
    std::optional<Error> object(const json& v, std::string_view section, const std::string& at, void* owner,
                                std::string_view extraKeys = {}) const {
        if (!v.is_object()) return fail(at, "expected an object, got " + jsonExcerpt(v));
        for (const auto& [key, value] : v.items()) {
            if (!extraKeys.empty() && isListed(extraKeys, key)) continue;
            const Field* f = find(section, key);
            if (!f) return fail(at + "." + key, "unknown key (expected one of: " + known(section, extraKeys) + ")");
            if (auto e = assign(*f, value, at + "." + key, owner)) return e;
        }
        return std::nullopt;
    }

    static const Field* find(std::string_view section, std::string_view key) {
        for (const Field& f : kFields) {
            if (f.section == section && f.key == key) return &f;
        }
        return nullptr;
    }
    static std::string known(std::string_view section, std::string_view extraKeys) {
        std::string out;
        for (const Field& f : kFields) {
            if (f.section == section) out += (out.empty() ? "" : ", ") + std::string(f.key);
        }
        if (!extraKeys.empty()) out += ", " + std::string(extraKeys);
        return out;
    }
    static bool isListed(std::string_view list, const std::string& key) {
        std::stringstream ss{std::string(list)};
        for (std::string item; std::getline(ss, item, ',');) {
            item.erase(0, item.find_first_not_of(' '));
            if (item == key) return true;
        }
        return false;
    }

private:
    std::string m_source;
};

std::optional<Error> checkScale(const Checker& check, const GhostParams& g, const std::string& at) {
    if (std::abs(g.scale) < kMinGhostScale) {
        return check.fail(at + ".scale", "expected |scale| >= 0.05 (a ghost that small magnifies one bloom texel over the frame), got " +
                                             std::to_string(g.scale));
    }
    return std::nullopt;
}

std::optional<Error> series(const Checker& check, const json& v, PostFxParams& p) {
    const std::string at = "ghost_series";
    GhostParams base;
    if (auto e = check.object(v, "ghost", at, &base, kSeriesKeys)) return e;
    double count = 0, spacing = 0.25, start = 1;
    if (auto it = v.find("count"); it != v.end()) {
        if (auto e = check.number(*it, at + ".count", 0, kMaxGhosts, count, true)) return e;
    } else {
        return check.fail(at + ".count", "missing; expected an integer in [0, 32]");
    }
    if (auto it = v.find("spacing"); it != v.end()) {
        if (auto e = check.number(*it, at + ".spacing", -16, 16, spacing, false)) return e;
    }
    if (auto it = v.find("start"); it != v.end()) {
        if (auto e = check.number(*it, at + ".start", -16, 16, start, false)) return e;
    }
    std::vector<Rgb> tints;
    if (auto it = v.find("tints"); it != v.end()) {
        if (!it->is_array() || it->empty() || it->size() > std::size_t(kMaxGhosts)) {
            return check.fail(at + ".tints", "expected an array of 1 to 32 colours, got " + jsonExcerpt(*it));
        }
        for (std::size_t i = 0; i < it->size(); ++i) {
            Rgb c{};
            if (auto e = check.color((*it)[i], at + ".tints[" + std::to_string(i) + "]", 0, 100, c)) return e;
            tints.push_back(c);
        }
    }
    for (int i = 0; i < int(count); ++i) {
        GhostParams g = base;
        g.scale = float(start - double(i) * spacing);
        if (!tints.empty()) g.tint = tints[std::size_t(i) % tints.size()];
        if (auto e = checkScale(check, g, at + " ghost " + std::to_string(i))) return e;
        p.ghosts.push_back(g);
    }
    return std::nullopt;
}

}  // namespace

Result<PostFxParams> parsePostFxPreset(const std::string& jsonText, const std::string& source) {
    auto parsed = parseJsonText(jsonText, source);
    if (!parsed) return parsed.error();
    const json& doc = *parsed;
    Checker check(source);
    if (!doc.is_object()) return check.fail("(top level)", "expected an object, got " + jsonExcerpt(doc));
    PostFxParams p;
    p.name = fs::path(source).stem().string();
    const std::string sections = "name, description, flare_intensity, bright, bloom, ghosts, ghost_series, halo, streaks, chromatic, starburst, dirt, tonemap";
    for (const auto& [key, value] : doc.items()) {
        if (key == "name" || key == "description") {
            if (!value.is_string()) return check.fail(key, "expected a string, got " + jsonExcerpt(value));
            (key == "name" ? p.name : p.description) = value.get<std::string>();
        } else if (key == "flare_intensity") {
            if (auto e = check.assign(*Checker::find("", key), value, key, &p)) return *e;
        } else if (key == "ghosts") {
            if (!value.is_array() || value.size() > std::size_t(kMaxGhosts)) {
                return check.fail(key, "expected an array of at most 32 ghosts, got " + jsonExcerpt(value));
            }
            for (std::size_t i = 0; i < value.size(); ++i) {
                const std::string at = "ghosts[" + std::to_string(i) + "]";
                GhostParams g;
                if (auto e = check.object(value[i], "ghost", at, &g)) return *e;
                if (auto e = checkScale(check, g, at)) return *e;
                p.ghosts.push_back(g);
            }
        } else if (key == "ghost_series") {
            if (auto e = series(check, value, p)) return *e;
        } else if (key == "bright" || key == "bloom" || key == "halo" || key == "streaks" || key == "chromatic" ||
                   key == "starburst" || key == "dirt" || key == "tonemap") {
            if (auto e = check.object(value, key, key, &p)) return *e;
        } else {
            return check.fail(key, "unknown key (expected one of: " + sections + ")");
        }
    }
    if (p.ghosts.size() > std::size_t(kMaxGhosts)) {
        return check.fail("ghosts", "expected at most 32 ghosts with ghost_series included, got " + std::to_string(p.ghosts.size()));
    }
    return p;
}

std::vector<std::string> shippedPostFxPresetNames() { return presetNamesIn("postfx"); }

Result<PostFxParams> loadPostFxPreset(const std::string& nameOrPath) {
    std::string path;
    auto text = readPresetText(nameOrPath, "postfx", path);
    if (!text) return text.error();
    return parsePostFxPreset(*text, path);
}

std::string postFxParameterReference() {
    std::ostringstream os;
    os << "| section | key | range | unit | meaning |\n|---|---|---|---|---|\n";
    for (const Field& f : kFields) {
        std::string r = range(f.min, f.max);
        if (f.kind == Kind::Color) r = "3 x " + r;
        if (f.kind == Kind::Bool) r = "true, false";
        if (f.kind == Kind::Filter) r = "`point`, `bilinear`";
        if (f.kind == Kind::Tone) r = "`none`, `aces`, `filmic`";
        const std::string section = f.section.empty() ? "(top)" : f.section == "ghost" ? "ghosts[i], ghost_series" : std::string(f.section);
        os << "| " << section << " | `" << f.key << "` | " << r << " | " << f.unit << " | " << f.doc << " |\n";
    }
    os << "| ghost_series | `count` | [0, 32] | | ghosts in the series (required) |\n";
    os << "| ghost_series | `spacing` | [-16, 16] | | ghost i has scale start - i x spacing (Chapman's ghost spacing) |\n";
    os << "| ghost_series | `start` | [-16, 16] | | scale of ghost 0 (default 1: the plain mirror image) |\n";
    os << "| ghost_series | `tints` | 1-32 colours | linear RGB | per-ghost tints, cycled; overrides `tint` |\n";
    return os.str();
}

}  // namespace flarekit
