// SPDX-License-Identifier: Apache-2.0
// Preset JSON: parsed with nlohmann-json, read field by field through kElementParams and
// kPresetParams (flarekit/Elements.h, flarekit/Flare.h) so every message names the file, the
// field and what was expected.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/JsonText.h"
#include "core/ParamJson.h"
#include "core/PresetFiles.h"
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"
#include "flarekit/ParamText.h"

namespace flarekit {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string elementTypeList() {
    std::string names;
    for (int i = 0; i < kElementTypeCount; ++i) {
        names +=
            std::string(i ? ", " : "") + "\"" + std::string(elementTypeName(ElementType(i))) + "\"";
    }
    return names;
}

//! Largest texture side an image element may name: 8192 covers any engine's flare texture
//! (they are 64-2048 px) and bounds what a preset makes the reader allocate.
constexpr int kMaxTextureSide = 8192;

//! An image element's "texture": the file, relative to the preset's folder, read linear.
Status readTexture(const json& value, const fs::path& baseDir, const JsonPlace& at,
                   ElementParams& p) {
    if (!value.is_string() || value.get<std::string>().empty())
        return at.fail("expected the file name of an image, got " + jsonExcerpt(value));
    p.texture = value.get<std::string>();
    const fs::path file =
        fs::path(p.texture).is_absolute() ? fs::path(p.texture) : baseDir / fs::path(p.texture);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        return at.fail("expected an image file, '" + file.string() + "' does not exist");
    auto loaded = readImage(file.string(), JobMemory{32, 0, "preset texture"});
    if (!loaded) return at.fail(loaded.error().message);
    if (loaded->image.width() > kMaxTextureSide || loaded->image.height() > kMaxTextureSide) {
        return at.fail("expected a texture of at most " + std::to_string(kMaxTextureSide) +
                       " pixels a side, got " + std::to_string(loaded->image.width()) + "x" +
                       std::to_string(loaded->image.height()));
    }
    p.textureImage = std::make_shared<const Image>(std::move(loaded->image));
    return Ok{};
}

Result<ElementParams> readElement(const json& e, const JsonPlace& at, const fs::path& baseDir) {
    if (!e.is_object()) return at.fail("expected an object, got " + jsonExcerpt(e));
    const auto typeIt = e.find("type");
    if (typeIt == e.end())
        return (at / "type").fail("missing; expected one of " + elementTypeList());
    auto type = typeIt->is_string() ? parseElementType(typeIt->get<std::string>()) : std::nullopt;
    if (!type)
        return (at / "type")
            .fail("expected one of " + elementTypeList() + ", got " + jsonExcerpt(*typeIt));
    ElementParams p = defaultElement(*type);
    const bool image = *type == ElementType::Image;
    if (auto err = image ? readParams<ElementParams>(e, kElementParams, p, at,
                                                     {"type", "texture", "source"}, typeBit(*type),
                                                     elementTypeName(*type))
                         : readParams<ElementParams>(e, kElementParams, p, at, {"type", "source"},
                                                     typeBit(*type), elementTypeName(*type))) {
        return *err;
    }
    if (const auto src = e.find("source"); src != e.end()) {
        if (!src->is_object())
            return (at / "source").fail("expected an object, got " + jsonExcerpt(*src));
        p.source = src->dump();
    }
    const auto tex = e.find("texture");
    if (!image) return p;
    if (tex == e.end()) return (at / "texture").fail("missing; expected the file of the image");
    if (Status s = readTexture(*tex, baseDir, at / "texture", p); !s) return s.error();
    return p;
}

}  // namespace

Status validatePreset(const Preset& preset) {
    if (Status s = validateParams<Preset>(preset, kPresetParams, ""); !s) return s;
    if (preset.elements.empty() || preset.elements.size() > kMaxPresetElements) {
        return invalidInput("elements: expected 1 to " + std::to_string(kMaxPresetElements) +
                            " elements, got " + std::to_string(preset.elements.size()));
    }
    for (std::size_t i = 0; i < preset.elements.size(); ++i) {
        const ElementParams& e = preset.elements[i];
        const std::string at = "element[" + std::to_string(i) + "].";
        if (int(e.type) < 0 || int(e.type) >= kElementTypeCount) {
            return invalidInput(at + "type: expected one of " + elementTypeList());
        }
        if (Status s = validateParams<ElementParams>(e, kElementParams, at, typeBit(e.type)); !s)
            return s;
        if (e.type == ElementType::Image && !e.textureImage)
            return invalidInput(at + "texture: expected the image of an image element");
    }
    return Ok{};
}

Result<Preset> parsePreset(const std::string& jsonText, const std::string& source) {
    auto parsed = parseJsonText(jsonText, source);
    if (!parsed) return parsed.error();
    const json& doc = *parsed;
    const JsonPlace top(source);
    if (!doc.is_object()) return top.fail("expected an object, got " + jsonExcerpt(doc));
    Preset preset;
    preset.name = fs::path(source).stem().string();
    const fs::path baseDir = fs::path(source).parent_path();
    for (const auto& [key, value] : doc.items()) {
        if (key == "name" || key == "description") {
            if (!value.is_string())
                return (top / key).fail("expected a string, got " + jsonExcerpt(value));
            (key == "name" ? preset.name : preset.description) = value.get<std::string>();
        } else if (key == "source") {
            if (!value.is_object())
                return (top / key).fail("expected an object, got " + jsonExcerpt(value));
            preset.source = value.dump();
        } else if (key == "elements") {
            if (!value.is_array() || value.empty() || value.size() > kMaxPresetElements) {
                return (top / key).fail("expected an array of 1 to " +
                                        std::to_string(kMaxPresetElements) + " elements, got " +
                                        jsonExcerpt(value));
            }
            for (std::size_t i = 0; i < value.size(); ++i) {
                auto element =
                    readElement(value[i], JsonPlace(source, "element").index(i), baseDir);
                if (!element) return element.error();
                preset.elements.push_back(element.value());
            }
        } else if (const Param<Preset>* p = findParam<Preset>(kPresetParams, key)) {
            auto v = readParamValue(*p, value, top / key);
            if (!v) return v.error();
            p->set(preset, *v);
        } else {
            return (top / key).fail(
                "unknown key (expected one of: name, description, intensity, elements, source)");
        }
    }
    if (preset.elements.empty())
        return (top / "elements").fail("missing; expected an array of elements");
    if (Status s = validatePreset(preset); !s)
        return invalidInput(source + ": " + s.error().message);
    return preset;
}

std::string presetToJson(const Preset& preset) {
    json doc;
    doc["name"] = preset.name;
    if (!preset.description.empty()) doc["description"] = preset.description;
    if (preset.intensity != Preset{}.intensity) doc["intensity"] = preset.intensity;
    if (json src = json::parse(preset.source, nullptr, false); src.is_object())
        doc["source"] = std::move(src);
    doc["elements"] = json::array();
    for (const ElementParams& e : preset.elements) {
        json element =
            writeParams<ElementParams>(e, kElementParams, defaultElement(e.type), typeBit(e.type));
        element["type"] = std::string(elementTypeName(e.type));
        // One colour where the type's default has a gradient: written, or reading it back would
        // bring the default's inner colour back.
        if (!e.innerColor && defaultElement(e.type).innerColor)
            element["inner_color"] = {e.color[0], e.color[1], e.color[2]};
        if (e.type == ElementType::Image) element["texture"] = e.texture;
        if (json src = json::parse(e.source, nullptr, false); src.is_object())
            element["source"] = std::move(src);
        doc["elements"].push_back(std::move(element));
    }
    // One element per line, as the shipped presets are written.
    std::string text = "{\n";
    for (auto it = doc.begin(); it != doc.end(); ++it) {
        if (it.key() == "elements") continue;
        text += "  \"" + it.key() + "\": " + it.value().dump() + ",\n";
    }
    text += "  \"elements\": [\n";
    for (std::size_t i = 0; i < doc["elements"].size(); ++i)
        text +=
            "    " + doc["elements"][i].dump() + (i + 1 < doc["elements"].size() ? ",\n" : "\n");
    return text + "  ]\n}\n";
}

std::vector<std::string> shippedPresetNames() {
    return presetNamesIn("");
}

Result<Preset> loadPreset(const std::string& nameOrPath) {
    return loadPresetFile(nameOrPath, "", parsePreset);
}

std::string presetParameterReference() {
    std::ostringstream os;
    os << "| key | applies to | range | unit | meaning |\n|---|---|---|---|---|\n";
    os << "| `type` | all | ";
    for (int i = 0; i < kElementTypeCount; ++i)
        os << (i ? ", " : "") << "`" << elementTypeName(ElementType(i)) << "`";
    os << " | | element kind (required) |\n";
    const auto none = [](const Param<ElementParams>&) { return std::string(); };
    os << markdownRows<ElementParams>(
        kElementParams, nullptr, none, [](const Param<ElementParams>& f) {
            if ((f.appliesTo & kAllElementTypes) == kAllElementTypes) return std::string("all | ");
            std::string types;
            for (int i = 0; i < kElementTypeCount; ++i) {
                if (f.appliesTo & typeBit(ElementType(i))) {
                    types +=
                        (types.empty() ? "" : ", ") + std::string(elementTypeName(ElementType(i)));
                }
            }
            return types + " | ";
        });
    os << "\nDefaults per type:\n\n| type | size | color | inner_color | intensity | type-specific "
          "|\n|---|---|---|---|---|---|\n";
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
            case ElementType::Ring:
                os << "width " << p.width;
                break;
            case ElementType::Streaks:
                os << "count " << p.count << ", thickness " << p.thickness << ", falloff "
                   << p.falloff;
                break;
            case ElementType::Rays:
                os << "count " << p.count << ", thickness " << p.thickness << ", falloff "
                   << p.falloff << ", min_length " << p.minLength << ", seed " << p.seed;
                break;
            case ElementType::Disc:
                os << "softness " << p.softness;
                break;
            case ElementType::Polygon:
                os << "blades " << p.blades << ", softness " << p.softness;
                break;
            case ElementType::EdgeStreak:
                os << "aspect " << p.aspect << ", reach " << p.reach
                   << " (placed on the frame edge; t unused)";
                break;
            case ElementType::Image:
                os << "texture (required): an image file, relative to the preset's folder";
                break;
            case ElementType::Glow:
                break;
        }
        os << " |\n";
    }
    os << "\nEvery element also takes `t` (default 1), `aspect` (1), `rotation` (0) and `blend` "
          "(`add`).\n";
    return os.str();
}

}  // namespace flarekit
