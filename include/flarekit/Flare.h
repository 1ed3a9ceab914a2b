// Sprite lens flares (Michael Tanczos, "The Art of Modeling Lens Flares", 1999): a preset's
// elements placed along the flare vector from the screen centre through the light, composited onto
// a linear-light image.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Elements.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"

namespace flarekit {

struct Preset {
    std::string name;
    std::string description;
    float intensity = 1.f;  //!< multiplies every element
    std::vector<ElementParams> elements;
};

inline constexpr Param<Preset> kPresetParams[] = {
    param<&Preset::intensity>("intensity", 0, 1000, "", "multiplies every element"),
};

//! Most elements a preset may hold: far more than any real flare, small enough to bound work.
inline constexpr std::size_t kMaxPresetElements = 256;

//! Every field of a preset against kPresetParams and kElementParams: the check JSON presets
//! and presets built in code both go through ("element[3].size: expected ...").
Status validatePreset(const Preset& preset);

//! Parses and validates a preset. `source` names the file in error messages, e.g.
//! "my.json: element[3].size: expected a number in [0, 4], got \"big\"".
Result<Preset> parsePreset(const std::string& jsonText, const std::string& source);
//! A shipped preset by name (see presetSearchPath) or a JSON file by path.
Result<Preset> loadPreset(const std::string& nameOrPath);
//! Directories searched for shipped presets: $FLAREKIT_PRESET_PATH (colon-separated), then
//! the install's share/flarekit/presets, then the source tree's presets/.
std::vector<std::string> presetSearchPath();
//! Names of every preset found on the search path, sorted.
std::vector<std::string> shippedPresetNames();
//! Markdown reference of every element parameter (key, types, default, range, meaning),
//! generated from the same table that validates presets.
std::string presetParameterReference();

//! Continuous pixel coordinates: (0, 0) is the top-left corner, pixel (i, j) has its centre
//! at (i + 0.5, j + 0.5), +y is down.
struct Point {
    float x = 0.f, y = 0.f;
};

//! Seed 002, "The Lens Flare Vector": with the light at (h, k) relative to the screen centre,
//! an element at position t sits at t*(h, k), i.e. centre + t*(light - centre).
inline Point flareVectorPoint(Point light, int width, int height, float t) {
    const float cx = 0.5f * float(width), cy = 0.5f * float(height);
    return {cx + t * (light.x - cx), cy + t * (light.y - cy)};
}

struct FlareStats {
    std::size_t elementsDrawn = 0;
    std::size_t pixelsShaded = 0;  //!< pixels evaluated: the cost of the flare
};

//! Composites the preset's flare onto `image` in place, for a light at `light` (may be outside
//! the frame), everything scaled by `intensity`. Work is proportional to the pixels the
//! elements cover, never the whole image per element.
FlareStats renderFlare(Image& image, const Preset& preset, Point light, float intensity);

struct LightSearchOptions {
    //! No light unless the peak linear luminance reaches this. 0.5 linear is sRGB code 188: a
    //! light source in an 8-bit photo is near 255, while the brightest pixel of an overcast or
    //! indoor frame without a light is usually well below.
    float minLuminance = 0.5f;
    //! A light's pixels are those >= nearPeak * peak ("the pixels near the maximum");
    //! 0.9 keeps a clipped sun's disc and its hottest halo, not the whole sky.
    float nearPeak = 0.9f;
};
inline constexpr Param<LightSearchOptions> kLightSearchParams[] = {
    param<&LightSearchOptions::minLuminance>(
        "light-threshold", 0, 1e6, "linear",
        "--light auto: smallest peak linear luminance that counts as a light"),
    param<&LightSearchOptions::nearPeak>(
        "near-peak", 0, 1, "of the peak",
        "--light auto: a light's pixels are those at least this fraction of the peak"),
};

struct FoundLight {
    bool found = false;
    Point position;          //!< luminance-weighted centroid of the light's pixels
    float peak = 0.f;        //!< peak linear luminance in the image
    float brightness = 0.f;  //!< mean linear luminance of the light's pixels
    std::size_t pixels = 0;  //!< size of the light's connected region
    float flareScale =
        0.f;  //!< intensity for the flare: brightness up to 1, 1 + ln(brightness) above
};

//! The flare intensity for a light of this linear luminance: linear up to display white, then
//! 1 + ln(brightness), so an HDR sun of 50 gives a strong flare without washing out the frame.
float flareScaleForBrightness(float brightness);

//! `--light auto`: the brightest region, as the connected region (4-neighbours) of pixels
//! near the peak with the largest summed luminance.
FoundLight findLight(const Image& image, const LightSearchOptions& options = {});

}  // namespace flarekit

namespace flarekit {

struct ContactSheet {
    Image image;
    bool labelled = false;  //!< false when no font could be loaded (labels then left out)
};

//! `flarekit elements`: each element of the preset on black in a labelled grid cell of
//! cellSize pixels, in preset order.
Result<ContactSheet> renderContactSheet(const Preset& preset, int cellSize);

}  // namespace flarekit
