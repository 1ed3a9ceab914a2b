// SPDX-License-Identifier: Apache-2.0
// Flares in and out of other engines: PlayCanvas, Babylon.js, three.js and Unity (sprite
// flares: a flarekit Preset) and Unreal and Godot (screen-space flares: a post-process preset).
// docs/interop.md states each format's fields, its position and size conventions and their
// sources, and what does not map.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Result.h"

namespace flarekit {

enum class FlareFormat {
    Flarekit,    //!< a flarekit sprite or post-process preset (.json)
    PlayCanvas,  //!< a LensFlareLook JSON
    Babylon,     //!< a serialized LensFlareSystem JSON
    Three,       //!< a three.js Lensflare description JSON
    Unity,       //!< a Lens Flare (SRP) data asset (.asset, YAML)
    Unreal,      //!< post-process lens-flare settings (FPostProcessSettings as JSON or text)
    Godot,       //!< the Godot lens-flare add-on's node (.tscn) or its settings as JSON
};
//! The names `--from` and `--to` take, in FlareFormat's order.
inline constexpr std::string_view kFlareFormatNames[] = {
    "flarekit", "playcanvas", "babylon", "three", "unity", "unreal", "godot"};
std::optional<FlareFormat> parseFlareFormat(std::string_view name);
//! Whether a format holds post-process (screen-space) flares rather than sprite elements.
bool isPostFxFormat(FlareFormat format);

//! Unity's SRPLensFlareBlendMode changed order between package versions: early SRP 12 previews
//! serialised Lerp, Additive, Premultiply, Screen as 0..3; SRP 12.0 and later write Additive,
//! Screen, Premultiply, Lerp. Auto reads the early order only from assets of the early schema
//! (elements with `size` and `aspectRatio` instead of `sizeXY`).
enum class UnityBlendOrder { Auto, Current, Early };
inline constexpr std::string_view kUnityBlendOrderNames[] = {"auto", "current", "early"};

struct ConvertOptions {
    std::optional<FlareFormat> from;  //!< unset: from the file's extension and content
    std::optional<FlareFormat> to;    //!< unset: from the output's extension
    //! The screen the sizes are converted through: width / height. Babylon sizes are fractions
    //! of the half width, so an element's size in flarekit (a fraction of the height) depends on
    //! it; 16:9 is what the engines' templates are authored at.
    float aspect = 16.f / 9.f;
    //! three.js sizes are pixels: they are converted at this frame height.
    int referenceHeight = 1080;
    UnityBlendOrder unityBlendOrder = UnityBlendOrder::Auto;
    //! Unity textures are referenced by GUID: the folder searched for their .meta files
    //! (default: the asset's folder and its parents up to the project's Assets folder).
    std::string unityAssets;
};
inline constexpr Param<ConvertOptions> kConvertParams[] = {
    param<&ConvertOptions::aspect>("aspect", 0.1, 10, "width / height",
                                   "screen aspect the engines' sizes are converted through"),
    param<&ConvertOptions::referenceHeight>("reference_height", 16, 16384, "pixels",
                                            "frame height at which pixel sizes (three.js) "
                                            "are converted"),
    choice<&ConvertOptions::unityBlendOrder>(
        "unity_blend_order", kUnityBlendOrderNames,
        "Unity blendMode integers: `current` (SRP 12.0+: additive, screen, premultiply, lerp), "
        "`early` (SRP 12 previews: lerp, additive, premultiply, screen) or `auto`"),
};

//! A flare as flarekit holds it: sprite elements or a post-process chain, whichever the
//! format carries, plus the images its elements use (already read into the elements).
struct FlareAsset {
    bool postFx = false;
    Preset sprite;                      //!< !postFx
    PostFxParams chain;                 //!< postFx
    std::vector<std::string> warnings;  //!< one line per feature that did not map
};

//! The format of `path`: flarekit JSON, a JSON of one of the engines (by its keys), a Unity
//! .asset, a Godot .tscn or Unreal settings text; an error naming the file when none fits.
Result<FlareFormat> detectFlareFormat(const std::string& path);
//! The format an output path asks for by its extension (.asset: unity, .tscn: godot, .ini:
//! unreal); JSON outputs need `to`.
Result<FlareFormat> outputFlareFormat(const std::string& path, const ConvertOptions& options);

//! Reads any supported file into flarekit's model. Errors name the file, the field and what
//! was expected; warnings list what could not be mapped (kept in the preset's "source").
Result<FlareAsset> importFlare(const std::string& path, const ConvertOptions& options = {});
//! Writes `asset` as `format` to `path` (and its textures beside it), nothing written on error;
//! returns the warnings of what the format cannot hold.
Result<std::vector<std::string>> exportFlare(const FlareAsset& asset, const std::string& path,
                                             FlareFormat format,
                                             const ConvertOptions& options = {});

//! importFlare then exportFlare, the job of `flarekit convert`: the warnings of both.
Result<std::vector<std::string>> convertFlare(const std::string& input, const std::string& output,
                                              const ConvertOptions& options = {});

}  // namespace flarekit
