// SPDX-License-Identifier: Apache-2.0
// flarekit convert: which format a file is, reading it into flarekit's model, writing the model
// as another format with its textures beside it, nothing written unless everything succeeded.
#include <algorithm>
#include <cctype>

#include "convert/ConvertCommon.h"
#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/ParamText.h"

namespace flarekit {

using namespace convert;

namespace {

std::string lowerExt(const std::string& path) {
    std::string e = fs::path(path).extension().string();
    for (char& c : e) c = char(std::tolower((unsigned char)c));
    return e;
}

const char* const kPostFxKeys[] = {"ghosts",  "ghost_series", "bright",
                                   "bloom",   "halo",         "flare_intensity",
                                   "streaks", "chromatic",    "starburst"};

//! Which JSON this is, by its keys.
std::optional<FlareFormat> jsonFormat(const json& doc) {
    if (!doc.is_object()) return std::nullopt;
    if (doc.contains("flares")) return FlareFormat::Babylon;
    if (doc.contains("elements") && doc["elements"].is_array() && !doc["elements"].empty() &&
        doc["elements"][0].is_object()) {
        const json& e = doc["elements"][0];
        if (e.contains("type")) return FlareFormat::Flarekit;
        if (e.contains("distance") || e.contains("texture")) return FlareFormat::Three;
        if (e.contains("offset") || e.contains("shape")) return FlareFormat::PlayCanvas;
    }
    for (const char* k : kPostFxKeys)
        if (doc.contains(k)) return FlareFormat::Flarekit;
    for (const auto& [k, v] : doc.items()) {
        std::string l = k;
        for (char& c : l) c = char(std::tolower((unsigned char)c));
        if (l.rfind("lensflare", 0) == 0 || l == "settings") return FlareFormat::Unreal;
        if (k == "flareStrength" || k == "ghostCount" || k == "flareBias")
            return FlareFormat::Godot;
    }
    return std::nullopt;
}

Result<std::string> readInput(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return invalidInput(path + ": expected a flare file, it does not exist or is not a file");
    return readTextFile(path);
}

Result<FlareAsset> readFlarekit(const std::string& text, ImportContext& ctx) {
    auto parsed = parseJsonText(text, ctx.path);
    if (!parsed) return parsed.error();
    FlareAsset asset;
    const bool sprite = parsed->is_object() && parsed->contains("elements");
    if (!sprite) {
        auto chain = parsePostFxPreset(text, ctx.path);
        if (!chain) return chain.error();
        asset.postFx = true;
        asset.chain = std::move(*chain);
        return asset;
    }
    auto preset = parsePreset(text, ctx.path);
    if (!preset) return preset.error();
    // Textures by absolute path, so that a writer can copy them wherever it writes.
    for (ElementParams& e : preset->elements) {
        std::error_code ec;
        if (e.type == ElementType::Image)
            e.texture = fs::absolute(fs::path(e.texture).is_absolute() ? fs::path(e.texture)
                                                                       : ctx.dir / e.texture,
                                     ec)
                            .lexically_normal()
                            .string();
    }
    asset.sprite = std::move(*preset);
    return asset;
}

Result<std::string> writeFlarekit(const FlareAsset& asset, ExportContext& ctx) {
    if (asset.postFx) return postFxPresetToJson(asset.chain);
    Preset preset = asset.sprite;
    for (ElementParams& e : preset.elements) {
        if (e.type != ElementType::Image) continue;
        // A Unity texture's .meta travels with it: its GUID is how assets refer to it.
        std::error_code ec;
        if (fs::is_regular_file(e.texture + ".meta", ec)) ctx.addCopy(e.texture + ".meta");
        e.texture = ctx.addCopy(e.texture);
    }
    return presetToJson(preset);
}

//! Side files checked (nothing already there with other content), then written; the main file
//! last, so a reader never sees it before its textures.
Status writeAll(const std::string& path, const std::string& text, ExportContext& ctx) {
    const fs::path dir = fs::path(path).parent_path();
    if (Status s = checkWritablePath(path); !s) return s;
    for (const SideFile& f : ctx.files) {
        const fs::path target = dir / f.name;
        std::error_code ec;
        if (!f.copyOf.empty() && fs::equivalent(target, f.copyOf, ec)) continue;
        if (!fs::exists(target, ec)) continue;
        bool same = false;
        if (!f.copyOf.empty()) {
            auto a = readTextFile(target.string(), std::uintmax_t(1) << 30);
            auto b = readTextFile(f.copyOf, std::uintmax_t(1) << 30);
            same = a && b && *a == *b;
        }
        // A texture flarekit baked or a .meta it made is its own: rewritten in place.
        if (!same && !f.copyOf.empty())
            return invalidInput(target.string() +
                                ": a different file of that name is already beside the output; "
                                "move it or write elsewhere (nothing was written)");
    }
    for (const SideFile& f : ctx.files) {
        const fs::path target = dir / f.name;
        std::error_code ec;
        if (!f.copyOf.empty()) {
            if (fs::equivalent(target, f.copyOf, ec)) continue;
            auto bytes = readTextFile(f.copyOf, std::uintmax_t(1) << 30);
            if (!bytes) return bytes.error();
            if (Status s = writeFileSafely(target.string(), *bytes); !s) return s;
        } else if (!f.text.empty()) {
            if (Status s = writeFileSafely(target.string(), f.text); !s) return s;
        } else if (Status s = writeImage(target.string(), f.image); !s) {
            return s;
        }
    }
    return writeFileSafely(path, text);
}

}  // namespace

std::optional<FlareFormat> parseFlareFormat(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kFlareFormatNames); ++i)
        if (kFlareFormatNames[i] == name) return FlareFormat(i);
    return std::nullopt;
}

bool isPostFxFormat(FlareFormat format) {
    return format == FlareFormat::Unreal || format == FlareFormat::Godot;
}

Result<FlareFormat> detectFlareFormat(const std::string& path) {
    const std::string ext = lowerExt(path);
    if (ext == ".asset") return FlareFormat::Unity;
    if (ext == ".tscn") return FlareFormat::Godot;
    if (ext == ".ini" || ext == ".txt" || ext == ".t3d") return FlareFormat::Unreal;
    auto text = readInput(path);
    if (!text) return text.error();
    const std::string head = text->substr(0, 64);
    if (head.rfind("%YAML", 0) == 0) return FlareFormat::Unity;
    if (head.rfind("[gd_scene", 0) == 0) return FlareFormat::Godot;
    const json doc = json::parse(*text, nullptr, false);
    if (const auto f = jsonFormat(doc)) return *f;
    return invalidInput(path +
                        ": expected a flarekit preset, a Unity .asset, a Godot .tscn, or the "
                        "JSON of PlayCanvas, Babylon.js, three.js, Unreal or Godot flares "
                        "(docs/interop.md); pass --from FORMAT to name it");
}

Result<FlareFormat> outputFlareFormat(const std::string& path, const ConvertOptions& options) {
    if (options.to) return *options.to;
    const std::string ext = lowerExt(path);
    if (ext == ".asset") return FlareFormat::Unity;
    if (ext == ".tscn") return FlareFormat::Godot;
    if (ext == ".ini" || ext == ".txt" || ext == ".t3d") return FlareFormat::Unreal;
    return invalidInput(path +
                        ": --to: expected the output format (one of flarekit, "
                        "playcanvas, babylon, three, unity, unreal, godot); a .json "
                        "output does not tell which");
}

namespace {
Result<FlareAsset> importUnguarded(const std::string& path, const ConvertOptions& options) {
    if (Status s = validateParams<ConvertOptions>(options, kConvertParams, ""); !s)
        return s.error();
    FlareFormat format;
    if (options.from) {
        format = *options.from;
    } else {
        auto detected = detectFlareFormat(path);
        if (!detected) return detected.error();
        format = *detected;
    }
    auto text = readInput(path);
    if (!text) return text.error();
    std::vector<std::string> warnings;
    ImportContext ctx{path, fs::path(path).parent_path(), options, warnings};
    Result<FlareAsset> asset = invalidInput(path + ": unknown format");
    const auto asJson = [&](auto reader) -> Result<FlareAsset> {
        auto doc = parseJsonText(*text, path);
        if (!doc) return doc.error();
        if (!doc->is_object())
            return invalidInput(path + ": (top level): expected an object, got " +
                                jsonExcerpt(*doc));
        return reader(*doc, ctx);
    };
    switch (format) {
        case FlareFormat::Flarekit:
            asset = readFlarekit(*text, ctx);
            break;
        case FlareFormat::PlayCanvas:
            asset = asJson(readPlayCanvas);
            break;
        case FlareFormat::Babylon:
            asset = asJson(readBabylon);
            break;
        case FlareFormat::Three:
            asset = asJson(readThree);
            break;
        case FlareFormat::Unity:
            asset = readUnity(*text, ctx);
            break;
        case FlareFormat::Unreal:
            asset = readUnreal(*text, ctx);
            break;
        case FlareFormat::Godot:
            asset = readGodot(*text, ctx);
            break;
    }
    if (!asset) return asset.error();
    if (!asset->postFx) {
        if (Status s = validatePreset(asset->sprite); !s)
            return invalidInput(path + ": " + s.error().message);
    }
    asset->warnings.insert(asset->warnings.end(), warnings.begin(), warnings.end());
    return asset;
}

Result<std::vector<std::string>> exportUnguarded(const FlareAsset& asset, const std::string& path,
                                                 FlareFormat format,
                                                 const ConvertOptions& options) {
    if (Status s = validateParams<ConvertOptions>(options, kConvertParams, ""); !s)
        return s.error();
    const std::string name = std::string(kFlareFormatNames[int(format)]);
    if (format != FlareFormat::Flarekit && asset.postFx != isPostFxFormat(format)) {
        return invalidInput(path + ": " + name + " holds " +
                            (isPostFxFormat(format) ? "post-process (screen-space) flares"
                                                    : "sprite flares of elements") +
                            ", the input is a " +
                            (asset.postFx ? "post-process preset" : "sprite preset") +
                            "; convert " +
                            (asset.postFx ? "to unreal, godot or flarekit"
                                          : "to playcanvas, babylon, three, unity or flarekit"));
    }
    ExportContext ctx{path, fs::path(path).stem().string(), options, {}, {}};
    Result<std::string> text = internalError("no writer");
    switch (format) {
        case FlareFormat::Flarekit:
            text = writeFlarekit(asset, ctx);
            break;
        case FlareFormat::PlayCanvas:
            text = writePlayCanvas(asset.sprite, ctx);
            break;
        case FlareFormat::Babylon:
            text = writeBabylon(asset.sprite, ctx);
            break;
        case FlareFormat::Three:
            text = writeThree(asset.sprite, ctx);
            break;
        case FlareFormat::Unity:
            text = writeUnity(asset.sprite, ctx);
            break;
        case FlareFormat::Unreal:
            text = writeUnreal(asset.chain, ctx);
            break;
        case FlareFormat::Godot:
            text = writeGodot(asset.chain, ctx);
            break;
    }
    if (!text) return text.error();
    if (Status s = writeAll(path, *text, ctx); !s) return s.error();
    return ctx.warnings;
}

}  // namespace

// The readers and writers handle every error of a user's file as a Result; these guards turn
// anything a library below still throws (an allocation, a YAML corner case) into an error
// rather than let it cross the API.
Result<FlareAsset> importFlare(const std::string& path, const ConvertOptions& options) {
    try {
        return importUnguarded(path, options);
    } catch (const std::exception& e) {
        return internalError(path + ": reading the flare failed: " + e.what());
    }
}

Result<std::vector<std::string>> exportFlare(const FlareAsset& asset, const std::string& path,
                                             FlareFormat format, const ConvertOptions& options) {
    try {
        return exportUnguarded(asset, path, format, options);
    } catch (const std::exception& e) {
        return internalError(path + ": writing the flare failed: " + e.what());
    }
}

Result<std::vector<std::string>> convertFlare(const std::string& input, const std::string& output,
                                              const ConvertOptions& options) {
    std::error_code ec;
    if (fs::exists(output, ec) && fs::equivalent(input, output, ec))
        return invalidInput(output + ": the output would replace the input; write elsewhere");
    auto to = outputFlareFormat(output, options);
    if (!to) return to.error();
    auto asset = importFlare(input, options);
    if (!asset) return asset.error();
    auto warnings = exportFlare(*asset, output, *to, options);
    if (!warnings) return warnings.error();
    std::vector<std::string> all = asset->warnings;
    all.insert(all.end(), warnings->begin(), warnings->end());
    return all;
}

}  // namespace flarekit
