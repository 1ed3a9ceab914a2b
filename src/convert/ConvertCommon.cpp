// SPDX-License-Identifier: Apache-2.0
#include "convert/ConvertCommon.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "convert/ExtensionBlock.h"
#include "flarekit/ImageIO.h"
#include "flarekit/ParamText.h"

namespace flarekit::convert {

namespace {
//! Texels from a baked element's centre to its rim: 120 gives a 256-texel texture for a round
//! element, finer than any of these engines draws a ghost at 1080p (a ghost of size 0.1 is
//! 108 px to its rim) and small enough to ship beside an asset.
constexpr float kBakeRadius = 120.f;
}  // namespace

std::string ExportContext::addCopy(const std::string& source) {
    const std::string base = fs::path(source).filename().string();
    std::string name = base;
    for (int n = 2;; ++n) {
        const auto same = std::find_if(files.begin(), files.end(),
                                       [&](const SideFile& f) { return f.name == name; });
        if (same == files.end()) break;
        if (same->copyOf == source) return name;
        name = fs::path(base).stem().string() + "-" + std::to_string(n) +
               fs::path(base).extension().string();
    }
    files.push_back({name, source, {}, {}});
    return name;
}

std::string ExportContext::addBaked(const ElementParams& element, int index, float& radiusShare,
                                    float& gain) {
    ElementParams e = element;
    e.intensity = 1.f;
    Image shape = renderElement(e, kBakeRadius);
    // An 8-bit texture holds [0, 1]: brighter colours (HDR inner colours) go into the gain the
    // engine multiplies the texture by.
    float peak = 0.f;
    for (int y = 0; y < shape.height(); ++y)
        for (int x = 0; x < shape.width(); ++x) {
            const Rgba& p = shape.at(x, y);
            peak = std::max({peak, p.r, p.g, p.b});
        }
    gain = element.intensity * std::max(peak, 1.f);
    if (peak > 1.f) {
        for (int y = 0; y < shape.height(); ++y)
            for (int x = 0; x < shape.width(); ++x) {
                Rgba& p = shape.at(x, y);
                p.r /= peak, p.g /= peak, p.b /= peak;
            }
    }
    const int side = std::max(shape.width(), shape.height());
    Image square(side, side);
    const int ox = (side - shape.width()) / 2, oy = (side - shape.height()) / 2;
    for (int y = 0; y < shape.height(); ++y)
        for (int x = 0; x < shape.width(); ++x) square.at(x + ox, y + oy) = shape.at(x, y);
    radiusShare = kBakeRadius / (0.5f * float(side));
    const std::string name = stem + "-" + std::to_string(index) + "-" +
                             std::string(elementTypeName(element.type)) + ".png";
    files.push_back({name, {}, std::move(square), {}});
    return name;
}

double tidy(double x) {
    // 6 significant digits: a float carries 7, and the conversions' arithmetic in float costs
    // the last one (700 px through a fraction of the height comes back as 699.99994).
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return std::strtod(buf, nullptr);
}

json tidied(const json& v) {
    if (v.is_number_float()) return tidy(v.get<double>());
    if (v.is_structured()) {
        json out = v;
        for (auto& x : out) x = tidied(x);
        return out;
    }
    return v;
}

std::string dumpByLine(const json& raw, const char* listKey) {
    const json doc = tidied(raw);
    std::string text = "{\n";
    for (auto it = doc.begin(); it != doc.end(); ++it) {
        if (it.key() == listKey) continue;
        text += "  " + json(it.key()).dump() + ": " + it.value().dump() + ",\n";
    }
    text += "  " + json(listKey).dump() + ": [\n";
    const json& list = doc[listKey];
    for (std::size_t i = 0; i < list.size(); ++i)
        text += "    " + list[i].dump() + (i + 1 < list.size() ? ",\n" : "\n");
    return text + "  ]\n}\n";
}

TexturedQuad texturedQuad(const ElementParams& e, std::size_t index, float presetIntensity,
                          const char* engine, ExportContext& ctx) {
    const std::string label = elementLabel(e, index);
    TexturedQuad q;
    const float k = e.intensity * presetIntensity;
    if (e.type == ElementType::Image) {
        q.texture = ctx.addCopy(e.texture);
        q.radius = e.size * std::max(1.f, e.aspect);
        q.color = {e.color[0] * k, e.color[1] * k, e.color[2] * k};
        if (e.aspect != 1.f || e.rotationDeg != 0.f)
            ctx.warn(label + "aspect and rotation: " + engine +
                     " draws square, unrotated textures");
    } else {
        float share = 1.f, gain = 1.f;
        q.texture = ctx.addBaked(e, int(index), share, gain);
        q.radius = e.size / share;
        const float g = gain * presetIntensity;
        q.color = {g, g, g};
        q.extension = elementExtension(e);
        if (e.type == ElementType::EdgeStreak)
            ctx.warn(label + engine +
                     " places every element on the flare line, not on the "
                     "frame edge");
    }
    if (e.blend != BlendMode::Add)
        ctx.warn(label + "blend " + std::string(kBlendModeNames[int(e.blend)]) + ": " + engine +
                 " adds every element");
    return q;
}

Result<json> jsonOrText(const std::string& text, const std::string& path,
                        Result<json> (*readText)(const std::string&, const std::string&)) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{') return parseJsonText(text, path);
    return readText(text, path);
}

Result<double> readNumber(const json& object, const char* key, const JsonPlace& at,
                          std::optional<double> fallback, double min, double max) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (fallback) return *fallback;
        return (at / key).fail("missing; expected a number");
    }
    if (!it->is_number() || !std::isfinite(it->get<double>()) || it->get<double>() < min ||
        it->get<double>() > max) {
        return (at / key).fail(joinText("expected a number in ", formatParamRange(min, max),
                                        ", got ", jsonExcerpt(*it)));
    }
    return it->get<double>();
}

Result<int> readInt(const json& object, const char* key, const JsonPlace& at,
                    std::optional<int> fallback, int min, int max) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (fallback) return *fallback;
        return (at / key).fail("missing; expected an integer");
    }
    if (!it->is_number_integer() || it->get<long long>() < min || it->get<long long>() > max) {
        return (at / key).fail("expected an integer in [" + std::to_string(min) + ", " +
                               std::to_string(max) + "], got " + jsonExcerpt(*it));
    }
    return int(it->get<long long>());
}

Result<bool> readBool(const json& object, const char* key, const JsonPlace& at,
                      std::optional<bool> fallback) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (fallback) return *fallback;
        return (at / key).fail("missing; expected true or false");
    }
    if (it->is_boolean()) return it->get<bool>();
    if (it->is_number_integer() && (*it == 0 || *it == 1)) return *it == 1;
    return (at / key).fail("expected true or false, got " + jsonExcerpt(*it));
}

Result<std::string> readString(const json& object, const char* key, const JsonPlace& at,
                               std::optional<std::string> fallback) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (fallback) return *fallback;
        return (at / key).fail("missing; expected a string");
    }
    if (!it->is_string()) return (at / key).fail("expected a string, got " + jsonExcerpt(*it));
    return it->get<std::string>();
}

Result<Rgb> readRgb(const json& value, const JsonPlace& at, std::optional<float>* alpha) {
    const auto bad = [&] {
        return at.fail("expected a colour [r, g, b] of numbers in [0, 1000], got " +
                       jsonExcerpt(value));
    };
    std::vector<double> c;
    if (value.is_array() && (value.size() == 3 || value.size() == 4)) {
        for (const json& x : value) {
            if (!x.is_number()) return bad();
            c.push_back(x.get<double>());
        }
    } else if (value.is_object()) {
        for (const char* k : {"r", "g", "b", "a"}) {
            auto it = value.find(k);
            if (it == value.end())
                it = value.find(std::string(1, char(std::toupper((unsigned char)k[0]))));
            if (it == value.end()) {
                if (k[0] == 'a') break;
                return bad();
            }
            if (!it->is_number()) return bad();
            c.push_back(it->get<double>());
        }
    } else {
        return bad();
    }
    for (std::size_t i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || c[i] < 0 || c[i] > 1000) return bad();
    if (alpha) *alpha = c.size() == 4 ? std::optional<float>(float(c[3])) : std::nullopt;
    return Rgb{float(c[0]), float(c[1]), float(c[2])};
}

json unmappedFields(const json& object, std::initializer_list<const char*> mapped) {
    json out = json::object();
    // Named references, not a structured binding: clang 14 cannot capture one in a lambda.
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string& key = it.key();
        if (std::none_of(mapped.begin(), mapped.end(), [&](const char* m) { return key == m; }))
            out[key] = it.value();
    }
    return out;
}

std::string sourceBlock(FlareFormat format, const json& fields) {
    if (fields.empty()) return {};
    return json{{"format", std::string(kFlareFormatNames[int(format)])}, {"fields", fields}}.dump();
}

bool isCountCopy(const ElementParams& e) {
    return fieldOr(json::parse(e.source, nullptr, false), "copy", false);
}

json sourceFields(const std::string& source, FlareFormat format) {
    const json s = json::parse(source, nullptr, false);
    if (fieldOr(s, "format", std::string()) != kFlareFormatNames[int(format)] ||
        !s.contains("fields") || !s["fields"].is_object())
        return json::object();
    return s["fields"];
}

Status loadTexture(ImportContext& ctx, const std::string& file, const JsonPlace& at,
                   ElementParams& e) {
    if (file.empty()) return at.fail("expected the file name of a texture, got \"\"");
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : ctx.dir / file;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        return at.fail("expected the texture file '" + file + "' beside " +
                       fs::path(ctx.path).filename().string() + ", '" + path.string() +
                       "' does not exist");
    }
    auto loaded = readImage(path.string(), JobMemory{32, 0, "flare texture"});
    if (!loaded) return at.fail(loaded.error().message);
    e.type = ElementType::Image;
    e.texture = fs::absolute(path, ec).lexically_normal().string();
    e.textureImage = std::make_shared<const Image>(std::move(loaded->image));
    return Ok{};
}

std::string elementLabel(const ElementParams& e, std::size_t index) {
    return "element[" + std::to_string(index) + "] (" + std::string(elementTypeName(e.type)) +
           "): ";
}

}  // namespace flarekit::convert
