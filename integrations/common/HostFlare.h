// SPDX-License-Identifier: Apache-2.0
// What every host plug-in does with one image it holds: a look (a sprite preset, a post-process
// preset or a lens) loaded once, then the library's pixel job for that look on the image, with
// the light found, placed or given by a tracker. The plug-ins differ only in how they get
// pixels and parameters from their host.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/Lens.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/job/PixelJob.h"

namespace flarekit::host {

//! Which of flarekit's flares a plug-in draws.
enum class FlareMode { Sprite, PostFx, Lens };
inline constexpr std::string_view kFlareModeNames[] = {"sprite", "postfx", "lens"};

//! The lens a lens-mode plug-in without a preset uses: a normal 50 mm prime, the lens most
//! footage and photographs are taken through.
inline constexpr const char* kDefaultHostLens = "asahi-takumar-50";

//! `name`, or the mode's default when it is empty.
std::string lookName(FlareMode mode, const std::string& name);
//! The shipped names a mode can use (sprite presets, post-process presets or lenses).
std::vector<std::string> lookNames(FlareMode mode);

//! A look loaded once for many images.
struct Look {
    FlareMode mode = FlareMode::Sprite;
    std::string name;
    std::optional<Preset> preset;
    std::shared_ptr<const PostFxParams> postFx;
    std::shared_ptr<const Lens> lens;

    //! The mode's preset or lens `name` (empty: the mode's default); errors as the CLI's.
    static Result<Look> load(FlareMode mode, const std::string& name);
};

struct FlareRequest {
    //! Where the light is, in pixels from the top-left; nothing: found in the image.
    std::optional<Point> light;
    //! A tracker's strength for `light` (its flare scale): drawn at that strength instead of
    //! measuring the light there.
    std::optional<float> lightScale;
    float intensity = 1;   //!< multiplies the flare (for every mode)
    double threshold = 0;  //!< > 0: a light's smallest linear luminance (the preset's own at 0)
    LightSearchOptions search;  //!< the light finder's options (threshold applied on top)
};

//! The light finder's options with the request's threshold.
LightSearchOptions searchOptions(const FlareRequest& request);

//! The look's flare on `input`: what `flarekit apply`, `postfx --expand-highlights` (for
//! display-referred input) or `lens render` write to a float EXR for the same image and light.
Result<Image> drawFlare(const Look& look, const FlareRequest& request, PixelInput input);

}  // namespace flarekit::host
