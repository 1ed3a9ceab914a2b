// SPDX-License-Identifier: Apache-2.0
// What every format's reader and writer share: the one position convention, typed field reads
// with one-line errors, the "source" blocks that keep what does not map, and textures.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/JsonText.h"
#include "core/ParamJson.h"
#include "flarekit/Convert.h"

namespace flarekit::convert {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Positions. Inside the converter every engine's position is first expressed as u: 0 on the
// light, 1 at the screen centre, 2 at the light's mirror point (the engines' own convention,
// give or take a factor). A flarekit preset's `t` is 1 at the light, 0 at the centre, -1 at
// the mirror point (seed 002's flare vector), so t = 1 - u.
inline float tFromU(double u) {
    return float(1.0 - u);
}
inline double uFromT(float t) {
    return 1.0 - double(t);
}

//! What a reader needs: where the file is, the options, and where its warnings go.
struct ImportContext {
    std::string path;  //!< as given, for messages
    fs::path dir;      //!< the file's folder: textures are found relative to it
    const ConvertOptions& options;
    std::vector<std::string>& warnings;
    void warn(const std::string& what) { warnings.push_back(path + ": " + what); }
};

//! A file a writer makes beside its output (a texture copied or baked), written only once the
//! whole conversion has succeeded.
struct SideFile {
    std::string name;    //!< file name beside the output
    std::string copyOf;  //!< copy this file's bytes, or
    Image image;         //!< write this image (PNG, linear values sRGB-encoded), or
    std::string text;    //!< write this text (a Unity .meta)
};

struct ExportContext {
    std::string path;  //!< the output, for messages
    std::string stem;  //!< its file name without extension: baked textures are named after it
    const ConvertOptions& options;
    std::vector<std::string> warnings;
    std::vector<SideFile> files;
    void warn(const std::string& what) { warnings.push_back(path + ": " + what); }
    //! The name beside the output a texture at `source` will have (its own file name, made
    //! unique among this export's files).
    std::string addCopy(const std::string& source);
    //! A procedural element baked into a square texture (its colours, intensity 1, scaled into
    //! [0, 1]) and the name it will have; `radiusShare` receives the share of the quad's half
    //! side the element's radius fills, `gain` what the engine multiplies the texture by.
    std::string addBaked(const ElementParams& element, int index, float& radiusShare, float& gain);
};

//! A computed value to 6 significant digits, within a float's precision: 0.2 rather than
//! 0.20000000298023224 for a float 0.2 written as a double.
double tidy(double x);
//! Every number in `v` tidied.
json tidied(const json& v);
//! The document with its top-level keys one per line and each item of the array `listKey` on
//! a line of its own (how flarekit writes presets): readable, and diffs stay per element.
std::string dumpByLine(const json& doc, const char* listKey);

//! How an engine that draws only textured quads (Babylon.js, three.js) gets a flarekit element:
//! its own texture, or the element baked into one; the quad's radius (frame heights) and the
//! colour the engine multiplies the texture by; `extension` the element's keys when baked.
struct TexturedQuad {
    std::string texture;
    float radius = 0.f;
    Rgb color{1, 1, 1};
    json extension;  //!< null unless baked
};
//! Also warns (naming `engine`) of what such an engine cannot draw: aspect and rotation of a
//! texture, a frame-edge placement, a blend other than add.
TexturedQuad texturedQuad(const ElementParams& e, std::size_t index, float presetIntensity,
                          const char* engine, ExportContext& ctx);

//! The JSON of a file that is JSON (its first character '{') or else read by `readText`.
Result<json> jsonOrText(const std::string& text, const std::string& path,
                        Result<json> (*readText)(const std::string&, const std::string&));

// Typed reads: the value or one line naming the file, the field and what was expected.
Result<double> readNumber(const json& object, const char* key, const JsonPlace& at,
                          std::optional<double> fallback, double min = -1e9, double max = 1e9);
Result<int> readInt(const json& object, const char* key, const JsonPlace& at,
                    std::optional<int> fallback, int min, int max);
Result<bool> readBool(const json& object, const char* key, const JsonPlace& at,
                      std::optional<bool> fallback);
Result<std::string> readString(const json& object, const char* key, const JsonPlace& at,
                               std::optional<std::string> fallback);
//! [r, g, b] or [r, g, b, a] or {"r": .., "g": .., "b": ..} (upper- or lower-case keys).
Result<Rgb> readRgb(const json& value, const JsonPlace& at, std::optional<float>* alpha = nullptr);

//! `object[key]` when it is there and of type T, else `fallback`: never throws (nlohmann's
//! value() throws on a value of another type, and these values come from users' files).
template <class T>
T fieldOr(const json& object, const char* key, T fallback) {
    if (!object.is_object()) return fallback;
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if constexpr (std::is_same_v<T, std::string>) {
        return it->is_string() ? it->get<std::string>() : fallback;
    } else if constexpr (std::is_same_v<T, bool>) {
        return it->is_boolean() ? it->get<bool>() : fallback;
    } else if constexpr (std::is_same_v<T, json>) {
        return it->type() == fallback.type() ? *it : fallback;
    } else {
        return it->is_number() ? it->get<T>() : fallback;
    }
}
//! Whether an element is a copy an engine's count made (written back as the count, not itself).
bool isCountCopy(const ElementParams& e);

//! The first error among several reads, or nothing when all succeeded.
template <class... R>
std::optional<Error> firstError(const R&... results) {
    std::optional<Error> first;
    ((first = first ? first : (results ? std::nullopt : std::optional<Error>(results.error()))),
     ...);
    return first;
}

//! `object` without the keys that map: what goes into an element's or a preset's "source".
json unmappedFields(const json& object, std::initializer_list<const char*> mapped);
//! The "source" block of a converted element or preset: {"format": NAME, "fields": {...}}.
std::string sourceBlock(FlareFormat format, const json& fields);
//! The fields a source block of `format` kept (an empty object when it is of another format).
json sourceFields(const std::string& source, FlareFormat format);

//! Reads the texture at `file` (relative to ctx.dir) into `e` as an image element; the
//! message names `at` and the file when it is missing or not an image.
Status loadTexture(ImportContext& ctx, const std::string& file, const JsonPlace& at,
                   ElementParams& e);

//! "element[3] (polygon): " for warnings.
std::string elementLabel(const ElementParams& e, std::size_t index);

// The formats. Each reader takes the parsed document; each writer returns the file's text.
Result<FlareAsset> readPlayCanvas(const json& doc, ImportContext& ctx);
Result<std::string> writePlayCanvas(const Preset& preset, ExportContext& ctx);
Result<FlareAsset> readBabylon(const json& doc, ImportContext& ctx);
Result<std::string> writeBabylon(const Preset& preset, ExportContext& ctx);
Result<FlareAsset> readThree(const json& doc, ImportContext& ctx);
Result<std::string> writeThree(const Preset& preset, ExportContext& ctx);
Result<FlareAsset> readUnity(const std::string& text, ImportContext& ctx);
Result<std::string> writeUnity(const Preset& preset, ExportContext& ctx);
Result<FlareAsset> readUnreal(const std::string& text, ImportContext& ctx);
Result<std::string> writeUnreal(const PostFxParams& chain, ExportContext& ctx);
Result<FlareAsset> readGodot(const std::string& text, ImportContext& ctx);
Result<std::string> writeGodot(const PostFxParams& chain, ExportContext& ctx);

}  // namespace flarekit::convert
