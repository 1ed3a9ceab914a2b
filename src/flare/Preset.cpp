// Preset JSON: parsed with nlohmann-json, validated field by field against ParamTable so
// every message names the file, the field and what was expected.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/JsonText.h"
#include "flare/ParamTable.h"
#include "flare/PresetFiles.h"
#include "flarekit/Flare.h"

#ifndef FLAREKIT_SOURCE_PRESET_DIR
#define FLAREKIT_SOURCE_PRESET_DIR ""
#endif
#ifndef FLAREKIT_INSTALL_PRESET_DIR
#define FLAREKIT_INSTALL_PRESET_DIR ""
#endif

namespace flarekit {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

//! Most elements a preset may hold: far more than any real flare, small enough to bound work.
constexpr std::size_t kMaxElements = 256;

std::string formatRange(double lo, double hi) {
    std::ostringstream os;
    os << "[" << lo << ", " << hi << "]";
    return os.str();
}

std::string got(const json& value) { return jsonExcerpt(value); }

class Validator {
public:
    explicit Validator(std::string source) : m_source(std::move(source)) {}

    Error fail(const std::string& field, const std::string& what) const {
        return invalidInput(m_source + ": " + field + ": " + what);
    }

    std::optional<Error> number(const json& v, const std::string& field, double lo, double hi, double& out) const {
        if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo || v.get<double>() > hi) {
            return fail(field, "expected a number in " + formatRange(lo, hi) + ", got " + got(v));
        }
        out = v.get<double>();
        return std::nullopt;
    }

    std::optional<Error> integer(const json& v, const std::string& field, double lo, double hi, double& out) const {
        const bool isInt = v.is_number_integer() ||
                           (v.is_number_float() && std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>()));
        if (!isInt || v.get<double>() < lo || v.get<double>() > hi) {
            return fail(field, "expected an integer in " + formatRange(lo, hi) + ", got " + got(v));
        }
        out = v.get<double>();
        return std::nullopt;
    }

    std::optional<Error> color(const json& v, const std::string& field, double lo, double hi, Rgb& out) const {
        const auto bad = [&] {
            return fail(field, "expected an array of 3 numbers in " + formatRange(lo, hi) + ", got " + got(v));
        };
        if (!v.is_array() || v.size() != 3) return bad();
        for (std::size_t c = 0; c < 3; ++c) {
            if (!v[c].is_number() || !std::isfinite(v[c].get<double>()) || v[c].get<double>() < lo ||
                v[c].get<double>() > hi) {
                return bad();
            }
            out[c] = v[c].get<float>();
        }
        return std::nullopt;
    }

    std::optional<Error> field(const FieldSpec& spec, const json& v, const std::string& path, ElementParams& p) const {
        switch (spec.kind) {
            case FieldKind::Number: {
                double x = 0;
                if (auto e = number(v, path, spec.min, spec.max, x)) return e;
                p.*std::get<float ElementParams::*>(spec.member) = float(x);
                return std::nullopt;
            }
            case FieldKind::Integer: {
                double x = 0;
                if (auto e = integer(v, path, spec.min, spec.max, x)) return e;
                p.*std::get<int ElementParams::*>(spec.member) = int(x);
                return std::nullopt;
            }
            case FieldKind::Seed: {
                double x = 0;
                if (auto e = integer(v, path, spec.min, spec.max, x)) return e;
                p.*std::get<std::uint32_t ElementParams::*>(spec.member) = std::uint32_t(x);
                return std::nullopt;
            }
            case FieldKind::Color:
                return color(v, path, spec.min, spec.max, p.*std::get<Rgb ElementParams::*>(spec.member));
            case FieldKind::OptionalColor: {
                Rgb c{};
                if (auto e = color(v, path, spec.min, spec.max, c)) return e;
                p.*std::get<std::optional<Rgb> ElementParams::*>(spec.member) = c;
                return std::nullopt;
            }
            case FieldKind::Blend: {
                auto mode = v.is_string() ? parseBlendMode(v.get<std::string>()) : std::nullopt;
                if (!mode) return fail(path, "expected one of \"add\", \"screen\", \"over\", got " + got(v));
                p.*std::get<BlendMode ElementParams::*>(spec.member) = *mode;
                return std::nullopt;
            }
        }
        return std::nullopt;
    }

    Result<ElementParams> element(const json& e, std::size_t index) const {
        const std::string at = "element[" + std::to_string(index) + "]";
        if (!e.is_object()) return fail(at, "expected an object, got " + got(e));
        std::string typeNames;
        for (int i = 0; i < kElementTypeCount; ++i) {
            typeNames += std::string(i ? ", " : "") + "\"" + std::string(elementTypeName(ElementType(i))) + "\"";
        }
        const auto typeIt = e.find("type");
        if (typeIt == e.end()) return fail(at + ".type", "missing; expected one of " + typeNames);
        auto type = typeIt->is_string() ? parseElementType(typeIt->get<std::string>()) : std::nullopt;
        if (!type) return fail(at + ".type", "expected one of " + typeNames + ", got " + got(*typeIt));

        ElementParams p = defaultElement(*type);
        for (const auto& [key, value] : e.items()) {
            if (key == "type") continue;
            const auto fields = elementFields();
            const auto spec = std::find_if(fields.begin(), fields.end(), [&](const FieldSpec& f) {
                return f.key == key && (f.types & typeBit(*type));
            });
            if (spec == fields.end()) {
                std::string known = "type";
                for (const FieldSpec& f : fields) {
                    if (f.types & typeBit(*type)) known += ", " + std::string(f.key);
                }
                return fail(at + "." + key, "unknown key for a " + std::string(elementTypeName(*type)) +
                                                " (expected one of: " + known + ")");
            }
            if (auto err = field(*spec, value, at + "." + key, p)) return *err;
        }
        return p;
    }

private:
    std::string m_source;
};

}  // namespace

Result<Preset> parsePreset(const std::string& jsonText, const std::string& source) {
    auto parsed = parseJsonText(jsonText, source);
    if (!parsed) return parsed.error();
    const json& doc = *parsed;
    Validator check(source);
    if (!doc.is_object()) return check.fail("(top level)", "expected an object, got " + got(doc));
    Preset preset;
    preset.name = fs::path(source).stem().string();
    for (const auto& [key, value] : doc.items()) {
        if (key == "name" || key == "description") {
            if (!value.is_string()) return check.fail(key, "expected a string, got " + got(value));
            (key == "name" ? preset.name : preset.description) = value.get<std::string>();
        } else if (key == "intensity") {
            double x = 0;
            if (auto e = check.number(value, key, 0, 1000, x)) return *e;
            preset.intensity = float(x);
        } else if (key == "elements") {
            if (!value.is_array() || value.empty() || value.size() > kMaxElements) {
                return check.fail(key, "expected an array of 1 to " + std::to_string(kMaxElements) +
                                           " elements, got " + got(value));
            }
            for (std::size_t i = 0; i < value.size(); ++i) {
                auto element = check.element(value[i], i);
                if (!element) return element.error();
                preset.elements.push_back(element.value());
            }
        } else {
            return check.fail(key, "unknown key (expected one of: name, description, intensity, elements)");
        }
    }
    if (preset.elements.empty()) return check.fail("elements", "missing; expected an array of elements");
    return preset;
}

std::vector<std::string> presetSearchPath() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("FLAREKIT_PRESET_PATH")) {
        std::stringstream ss(env);
        for (std::string dir; std::getline(ss, dir, ':');) {
            if (!dir.empty()) dirs.push_back(dir);
        }
    }
    for (const char* dir : {FLAREKIT_INSTALL_PRESET_DIR, FLAREKIT_SOURCE_PRESET_DIR}) {
        if (*dir) dirs.emplace_back(dir);
    }
    return dirs;
}

std::vector<std::string> presetNamesIn(const std::string& subdir) {
    std::vector<std::string> names;
    for (const std::string& dir : presetSearchPath()) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(fs::path(dir) / subdir, ec)) {
            if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

Result<std::string> readPresetText(const std::string& nameOrPath, const std::string& subdir, std::string& path) {
    path = nameOrPath;
    const bool looksLikePath = nameOrPath.find('/') != std::string::npos ||
                               fs::path(nameOrPath).extension() == ".json";
    if (!looksLikePath) {
        path.clear();
        for (const std::string& dir : presetSearchPath()) {
            const fs::path candidate = fs::path(dir) / subdir / (nameOrPath + ".json");
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) {
                path = candidate.string();
                break;
            }
        }
        if (path.empty()) {
            std::string names;
            for (const std::string& n : presetNamesIn(subdir)) names += (names.empty() ? "" : ", ") + n;
            return invalidInput((subdir.empty() ? "preset '" : subdir + " preset '") + nameOrPath +
                                "': expected a JSON file or one of: " + (names.empty() ? "(no shipped presets found)" : names));
        }
    }
    return readTextFile(path);
}

std::vector<std::string> shippedPresetNames() { return presetNamesIn(""); }

Result<Preset> loadPreset(const std::string& nameOrPath) {
    std::string path;
    auto text = readPresetText(nameOrPath, "", path);
    if (!text) return text.error();
    return parsePreset(*text, path);
}

std::string presetParameterReference() {
    std::ostringstream os;
    os << "| key | applies to | range | unit | meaning |\n|---|---|---|---|---|\n";
    os << "| `type` | all | " ;
    for (int i = 0; i < kElementTypeCount; ++i) os << (i ? ", " : "") << "`" << elementTypeName(ElementType(i)) << "`";
    os << " | | element kind (required) |\n";
    for (const FieldSpec& f : elementFields()) {
        std::string types;
        if (f.types == kAllTypes) {
            types = "all";
        } else {
            for (int i = 0; i < kElementTypeCount; ++i) {
                if (f.types & (1u << unsigned(i))) types += (types.empty() ? "" : ", ") + std::string(elementTypeName(ElementType(i)));
            }
        }
        std::string range = f.kind == FieldKind::Blend ? "`add`, `screen`, `over`"
                            : f.kind == FieldKind::Color || f.kind == FieldKind::OptionalColor
                                ? "3 x " + formatRange(f.min, f.max)
                                : formatRange(f.min, f.max);
        os << "| `" << f.key << "` | " << types << " | " << range << " | " << f.unit << " | " << f.doc << " |\n";
    }
    os << "\nDefaults per type:\n\n| type | size | color | inner_color | intensity | type-specific |\n|---|---|---|---|---|---|\n";
    for (int i = 0; i < kElementTypeCount; ++i) {
        const ElementParams p = defaultElement(ElementType(i));
        auto rgb = [](const Rgb& c) {
            std::ostringstream s;
            s << "[" << c[0] << ", " << c[1] << ", " << c[2] << "]";
            return s.str();
        };
        os << "| " << elementTypeName(p.type) << " | " << p.size << " | " << rgb(p.color) << " | "
           << (p.innerColor ? rgb(*p.innerColor) : "= color") << " | " << p.intensity << " | ";
        switch (p.type) {
            case ElementType::Ring: os << "width " << p.width; break;
            case ElementType::Streaks: os << "count " << p.count << ", thickness " << p.thickness << ", falloff " << p.falloff; break;
            case ElementType::Rays:
                os << "count " << p.count << ", thickness " << p.thickness << ", falloff " << p.falloff
                   << ", min_length " << p.minLength << ", seed " << p.seed;
                break;
            case ElementType::Disc: os << "softness " << p.softness; break;
            case ElementType::Polygon: os << "blades " << p.blades << ", softness " << p.softness; break;
            case ElementType::Glow: break;
        }
        os << " |\n";
    }
    os << "\nEvery element also takes `t` (default 1), `aspect` (1), `rotation` (0) and `blend` (`add`).\n";
    return os.str();
}

}  // namespace flarekit
