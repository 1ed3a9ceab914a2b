// SPDX-License-Identifier: Apache-2.0
// Parameters of the image-based (post-process) lens flare, each struct followed by the table
// that describes its keys once (flarekit/Param.h): the preset reader, validatePostFxParams, the
// CLI's override flags and docs/postfx.md all read these tables.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"

namespace flarekit {

//! Most ghosts one chain evaluates: the length of the ghost pass's uniform arrays (injected
//! into the GLSL as a #define); 32 is far past the dozen of any real lens.
inline constexpr int kMaxGhosts = 32;
//! Most starburst spokes (the spoke table's size, also a GLSL #define).
inline constexpr int kMaxSpokes = 64;
//! Most bright sources a starburst radiates from (a GLSL #define too): the strongest lights.
inline constexpr int kMaxStarCentres = 4;

//! "Any sensible HDR value": 10^4 x diffuse white.
inline constexpr double kPostFxBig = 1e4;
inline constexpr double kPostFxSeedMax = 2147483647.0;

//! Soft-knee threshold on linear HDR (Unity's bloom prefilter curve), after an optional
//! highlight compression (FlareSim's "highlight compression": a soft ceiling, so a sun of
//! 30,000 lights the chain like a bright lamp instead of washing the frame).
struct BrightParams {
    float threshold = 1.0f;  //!< linear value where the flare starts
    float knee = 0.5f;       //!< width of the quadratic ease-in below the threshold
    float ceiling = 0.f;     //!< soft ceiling C: brightness b becomes C tanh(b / C); 0: off
    //! Threshold, knee, ceiling and the ghost, halo and streak thresholds are multiples of the
    //! frame's white (frameWhite) instead of absolute linear values.
    bool exposureRelative = false;
    //! A light is small: the most light, as the bright pass's mean over the frame in units of
    //! the frame's white (B), that bloom and the lens effects follow; a frame whose B is larger
    //! has them scaled by this / B. 0: off. With exposure_relative only.
    float areaReference = 0.f;
    //! Set by a caller that knows the frame's white better than its pixels do (display-referred
    //! input after --expand-highlights: 1); 0 measures it. Not read from JSON.
    float knownWhite = 0.f;
};
inline constexpr Param<BrightParams> kBrightParams[] = {
    param<&BrightParams::threshold>("threshold", 0, kPostFxBig, "linear",
                                    "bright-pass threshold: where the flare starts"),
    param<&BrightParams::knee>(
        "knee", 0, kPostFxBig, "linear",
        "soft knee half width: quadratic ease-in over [threshold - knee, threshold + knee]"),
    param<&BrightParams::ceiling>("ceiling", 0, kPostFxBig, "linear",
                                  "highlight compression: brightness b enters the chain as "
                                  "C tanh(b / C); 0 turns it off"),
    param<&BrightParams::exposureRelative>(
        "exposure_relative", 0, 1, "",
        "threshold, knee, ceiling and the ghost, halo and streak thresholds are multiples of "
        "the frame's white (its metered luminance / 0.18 for HDR, 1 for 8/16-bit data)"),
    param<&BrightParams::areaReference>(
        "area_reference", 0, kPostFxBig, "x white",
        "with exposure_relative: the most light bloom and ghosts, halo and streaks follow, as B, "
        "the bright pass's mean over the frame in units of its white (blender-data's suns "
        "0.0004-0.03, a sunlit yard filling a fifth of the frame 0.46); a frame over it has "
        "them scaled by this / B, so lights keep their flare and wide bright areas do not wash "
        "the frame; 0 turns it off"),
};

//! Downsample (13-tap dual filter) and progressive tent upsample into the 1/4-res bloom buffer.
struct BloomParams {
    float intensity = 0.05f;  //!< bloom added to the image
    int levels = 6;           //!< mip levels below full res, 1/2 ... 1/2^levels
    float spread = 1.0f;      //!< weight of each coarser level when upsampling
};
inline constexpr Param<BloomParams> kBloomParams[] = {
    param<&BloomParams::intensity>("intensity", 0, 100, "",
                                   "bloom added to the image (0: ghosts only)"),
    param<&BloomParams::levels>("levels", 2, 12, "mips",
                                "downsample levels, 1/2 .. 1/2^levels: the bloom's reach"),
    param<&BloomParams::spread>(
        "spread", 0, 1, "", "weight of each coarser level in the upsample (1: mean of all levels)"),
};

inline constexpr std::string_view kGhostFilterNames[] = {"point", "bilinear"};

//! The default border fade of ghosts and halo: an eighth of the buffer on each side is the
//! narrowest ease that a ghost magnified 2x (the seed's scale 0.5) still shows as a soft
//! gradient over a sixteenth of the frame rather than a ramp of a few pixels.
inline constexpr float kDefaultBorderFade = 0.125f;
//! The default share of a ghost tint's colour kept: half, so a purple ghost of a warm lamp is a
//! warm pink rather than the tint's own magenta, while the preset's colours still tell the
//! ghosts apart.
inline constexpr float kDefaultGhostSaturation = 0.5f;

//! One ghost: the seed's LensFlarePS with its uniforms, plus the modern falloff.
struct GhostParams {
    Rgb tint{1.f, 1.f, 1.f};  //!< vTint of the seed
    float scale =
        1.f;  //!< fTexScale: the ghost of a light at l appears at -l/scale, |scale| >= 0.05
    float blur =
        0.f;  //!< fBlurScale: step between samples, in bloom-buffer texels / 2 (seed units)
    int samples = 12;        //!< NumSamples
    float threshold = 0.1f;  //!< fThreshold, subtracted from each bloom sample
    float falloff =
        0.f;  //!< 0: none (seed); else weight (1 - |n| / sqrt 2)^falloff of the unblurred point n
    bool centered = false;  //!< false: the seed's sample offsets (+1, -1, -3, ...); true: symmetric
                            //!< about the point
    bool linearFilter =
        false;  //!< false: the seed's point sampler; true: bilinear (smoother magnified ghosts)
    //! Share of the bloom buffer, on each side, over which a tap's weight eases to 0, so the
    //! mirrored frame border never shows as a straight edge; 0 is the seed's hard cut.
    float borderFade = kDefaultBorderFade;
    //! How much of the tint's colour is kept (its luminance always is): 1 the seed's vTint, 0 a
    //! grey of the same luminance, so the ghost takes the colour of what it samples.
    float saturation = kDefaultGhostSaturation;
    //! A ghost magnified 1 / |scale| times spreads the light it samples over 1 / scale^2 the
    //! area, as a real lens's defocused ghost does: its brightness is multiplied by scale^2 when
    //! |scale| < 1. false: the seed's, every ghost as bright as what it samples (a magnified
    //! ghost of a lit window is a window-bright wash over a quarter of the frame).
    bool conserveArea = true;
};
//! Below |scale| 0.05 a ghost magnifies one bloom texel over the frame.
inline constexpr double kMinGhostScale = 0.05;
inline constexpr Param<GhostParams> kGhostParams[] = {
    param<&GhostParams::tint>("tint", 0, 100, "linear RGB", "the seed's vTint"),
    param<&GhostParams::scale>(
        "scale", -16, 16, "",
        "the seed's fTexScale: a light at l gives a ghost at -l / scale (|scale| >= 0.05)"),
    param<&GhostParams::blur>(
        "blur", 0, 16, "bloom texels",
        "the seed's fBlurScale: sample step along the ray is blur x samples bloom texels"),
    param<&GhostParams::samples>("samples", 1, 64, "", "the seed's NumSamples"),
    param<&GhostParams::threshold>("threshold", 0, kPostFxBig, "linear",
                                   "the seed's fThreshold, subtracted from every bloom sample"),
    param<&GhostParams::falloff>(
        "falloff", 0, 64, "",
        "0: none (seed); else (1 - |n|/sqrt 2)^falloff of the unblurred point n (Chapman)"),
    param<&GhostParams::centered>(
        "centered", 0, 1, "",
        "false: the seed's sample offsets 1, -1, -3, ...; true: symmetric about the point"),
    choice<&GhostParams::linearFilter>("filter", kGhostFilterNames,
                                       "\"point\" (the seed's PointSampler) or \"bilinear\""),
    param<&GhostParams::borderFade>(
        "border_fade", 0, 0.5, "buffer widths",
        "each tap eases to 0 over this share of the bloom buffer at its border, so no straight "
        "frame edge is mirrored; 0: the seed's hard cut"),
    param<&GhostParams::saturation>(
        "saturation", 0, 1, "",
        "share of the tint's colour kept (its luminance always is): 1 the seed's vTint, 0 grey, "
        "so the ghost takes the colour of what it samples"),
    param<&GhostParams::conserveArea>(
        "conserve_area", 0, 1, "",
        "a magnified ghost (|scale| < 1) is dimmed by scale^2, the area its light spreads over; "
        "false: the seed's, as bright as what it samples"),
};

//! `ghost_series`: `count` ghosts of scale start - i x spacing sharing the ghost keys.
struct GhostSeriesParams {
    int count = 0;  //!< ghosts in the series (a required key)
    float spacing = 0.25f;
    float start = 1.f;
};
inline constexpr Param<GhostSeriesParams> kGhostSeriesParams[] = {
    param<&GhostSeriesParams::count>("count", 0, kMaxGhosts, "", "ghosts in the series (required)"),
    param<&GhostSeriesParams::spacing>(
        "spacing", -16, 16, "", "ghost i has scale start - i x spacing (Chapman's ghost spacing)"),
    param<&GhostSeriesParams::start>("start", -16, 16, "",
                                     "scale of ghost 0 (default 1: the plain mirror image)"),
};

//! A ring around the screen centre (John Chapman's pseudo lens flare halo), aspect-correct.
struct HaloParams {
    float intensity = 0.f;   //!< 0 switches it off
    float radius = 0.5f;     //!< in half image heights
    float thickness = 0.1f;  //!< radial spread of the ring, half image heights
    float threshold = 0.1f;  //!< subtracted from each bloom sample
    float falloff = 5.f;     //!< (1 - |p| / sqrt 2)^falloff of the mid-radius sample point
    Rgb tint{1.f, 1.f, 1.f};
    float borderFade = kDefaultBorderFade;  //!< as GhostParams::borderFade
};
inline constexpr Param<HaloParams> kHaloParams[] = {
    param<&HaloParams::intensity>("intensity", 0, 100, "", "0 switches the halo off"),
    param<&HaloParams::radius>("radius", 0, 4, "half heights",
                               "ring radius about the centre (aspect-correct)"),
    param<&HaloParams::thickness>("thickness", 0, 2, "half heights", "radial spread of the ring"),
    param<&HaloParams::threshold>("threshold", 0, kPostFxBig, "linear",
                                  "subtracted from every bloom sample"),
    param<&HaloParams::falloff>(
        "falloff", 0, 64, "",
        "(1 - |p|/sqrt 2)^falloff of the ring's mid-radius sample point (Chapman uses 5)"),
    param<&HaloParams::tint>("tint", 0, 100, "linear RGB", "ring colour"),
    param<&HaloParams::borderFade>(
        "border_fade", 0, 0.5, "buffer widths",
        "each tap eases to 0 over this share of the bloom buffer at its border; 0: a hard cut"),
};

//! Anamorphic streaks: a long horizontal blur of the 1/4-res bright image.
struct StreakParams {
    float intensity = 0.f;       //!< 0 switches it off
    float length = 0.25f;        //!< half length, fraction of the image width
    float falloff = 4.f;         //!< exponential falloff along the streak, e^(-falloff |t|)
    float threshold = 0.f;       //!< subtracted from each sample
    Rgb tint{0.45f, 0.6f, 1.f};  //!< anamorphic lenses streak blue
};
inline constexpr Param<StreakParams> kStreakParams[] = {
    param<&StreakParams::intensity>("intensity", 0, 100, "",
                                    "0 switches the anamorphic streaks off"),
    param<&StreakParams::length>("length", 0, 2, "image widths", "half length of a streak"),
    param<&StreakParams::falloff>("falloff", 0, 64, "",
                                  "e^(-falloff t) along the streak, t = distance / length"),
    param<&StreakParams::threshold>("threshold", 0, kPostFxBig, "linear",
                                    "subtracted from the bright image first"),
    param<&StreakParams::tint>("tint", 0, 100, "linear RGB",
                               "streak colour (anamorphic lenses: blue)"),
};

//! Lateral chromatic aberration of the ghosts and halo: red and blue sampled radially apart.
struct ChromaticParams {
    float amount = 0.f;  //!< red at scale (1 + amount), blue at (1 - amount) about the centre
};
inline constexpr Param<ChromaticParams> kChromaticParams[] = {
    param<&ChromaticParams::amount>(
        "amount", 0, 0.5, "",
        "red at (1 + amount), blue at (1 - amount) times the distance from the centre"),
};

//! Procedural starburst modulation of ghosts and halo (angle about the screen centre).
enum class StarCentre { Lights, Frame };
inline constexpr std::string_view kStarCentreNames[] = {"lights", "frame"};

struct StarburstParams {
    float intensity = 0.f;   //!< 0 off, 1 full modulation
    int spokes = 12;         //!< number of rays
    float width = 0.15f;     //!< ray half width, fraction of the spoke spacing
    std::uint32_t seed = 1;  //!< per-ray random brightness
    //! lights: rays radiate from each of the frame's brightest sources (findLights, at most
    //! kMaxStarCentres; the brightest pixel when none convinces), so the star sits on the sun
    //! instead of reading as a second sun at the centre; frame: from the frame centre (Chapman).
    StarCentre centre = StarCentre::Lights;
    //! Where the rays radiate from, in uv (x right, y up from the bottom-left, as the passes
    //! sample): filled per frame by fitToFrame, not read from JSON.
    std::array<float, 2 * kMaxStarCentres> centresUv{0.5f, 0.5f};
    int centreCount = 1;
};
inline constexpr Param<StarburstParams> kStarburstParams[] = {
    param<&StarburstParams::intensity>("intensity", 0, 1, "",
                                       "0 off, 1 full modulation of ghosts and halo"),
    param<&StarburstParams::spokes>("spokes", 2, kMaxSpokes, "", "number of rays"),
    param<&StarburstParams::width>("width", 0.01, 1, "spoke spacings", "ray half width"),
    param<&StarburstParams::seed>("seed", 0, kPostFxSeedMax, "", "per-ray random brightness"),
    choice<&StarburstParams::centre>("centre", kStarCentreNames,
                                     "`lights`: rays from each bright source (up to 4); "
                                     "`frame`: from the frame centre"),
};

//! Procedural lens dirt: soft random specks and smudges that multiply bloom and flare.
struct DirtParams {
    float intensity = 0.f;  //!< 0 off; lens x (1 + intensity x dirt)
    int spots = 80;         //!< specks
    std::uint32_t seed = 7;
};
inline constexpr Param<DirtParams> kDirtParams[] = {
    param<&DirtParams::intensity>("intensity", 0, 100, "",
                                  "0 off; bloom and flare x (1 + intensity x dirt)"),
    param<&DirtParams::spots>("spots", 0, 4096, "", "dust specks (plus one smudge per ten)"),
    param<&DirtParams::seed>("seed", 0, kPostFxSeedMax, "", "placement of the specks"),
};

enum class ToneOperator { None, Aces, Filmic };
inline constexpr std::string_view kToneOperatorNames[] = {"none", "aces", "filmic"};

struct ToneParams {
    ToneOperator op = ToneOperator::None;  //!< none (linear, clipped on 8-bit), aces (Narkowicz
                                           //!< fit), filmic (Hable)
    float exposure = 1.f;                  //!< multiplies the image before the curve
};
inline constexpr Param<ToneParams> kToneParams[] = {
    choice<&ToneParams::op>("operator", kToneOperatorNames,
                            "\"none\", \"aces\" (Narkowicz fit) or \"filmic\" (Hable)"),
    param<&ToneParams::exposure>("exposure", 0, 1000, "", "multiplies the image before the curve"),
};

struct PostFxParams {
    std::string name;
    std::string description;
    BrightParams bright;
    BloomParams bloom;
    std::vector<GhostParams> ghosts;  //!< explicit ghosts first, then any "ghost_series" expanded
    HaloParams halo;
    StreakParams streaks;
    ChromaticParams chromatic;
    StarburstParams starburst;
    DirtParams dirt;
    ToneParams tone;
    float flareIntensity = 1.f;  //!< multiplies ghosts, halo and streaks
    //! Another engine's settings flarekit cannot run, as compact JSON (flarekit/Convert.h):
    //! kept so converting back restores them. Empty: none.
    std::string source;
};
inline constexpr Param<PostFxParams> kPostFxTopParams[] = {
    param<&PostFxParams::flareIntensity>("flare_intensity", 0, 1000, "",
                                         "multiplies ghosts, halo and streaks"),
};

//! Calls f(key, table, section) for each section of a preset with one struct, in the order the
//! docs list them: the JSON reader and writer, and the studio's panel, walk the same list.
template <class P, class F>
void forEachPostFxSection(P& p, F&& f) {
    f("bright", std::span<const Param<BrightParams>>(kBrightParams), p.bright);
    f("bloom", std::span<const Param<BloomParams>>(kBloomParams), p.bloom);
    f("halo", std::span<const Param<HaloParams>>(kHaloParams), p.halo);
    f("streaks", std::span<const Param<StreakParams>>(kStreakParams), p.streaks);
    f("chromatic", std::span<const Param<ChromaticParams>>(kChromaticParams), p.chromatic);
    f("starburst", std::span<const Param<StarburstParams>>(kStarburstParams), p.starburst);
    f("dirt", std::span<const Param<DirtParams>>(kDirtParams), p.dirt);
    f("tonemap", std::span<const Param<ToneParams>>(kToneParams), p.tone);
}

//! Every field against the tables above, plus at most kMaxGhosts ghosts of |scale| >= 0.05:
//! the one check of JSON presets and of params built in code ("bloom.levels: expected ...").
Status validatePostFxParams(const PostFxParams& params);

//! The frame's white, the luminance its exposure maps to display white: 1 for display-referred
//! data (no pixel above 1), else its metered luminance (the mean, highlights clipped at 8 x the
//! median, as a camera's average meter reads a scene) / 0.18, middle grey's share of white, so
//! an HDR frame exposed anywhere gets the same flare.
float frameWhite(const Image& image);

//! `params` fitted to one frame: with bright.exposure_relative every threshold and the ceiling
//! multiplied by frameWhite(input); with a starburst centred on `lights`, its centres at the
//! frame's strongest lights. What both executors run.
PostFxParams fitToFrame(const PostFxParams& params, const Image& input);

//! Parses and validates a preset; messages read "source: field: expected ..., got ...".
Result<PostFxParams> parsePostFxPreset(const std::string& jsonText, const std::string& source);
//! The preset as JSON that parsePostFxPreset reads back to the same params: each section's keys
//! that differ from their defaults, and every ghost (a ghost_series is written as its ghosts).
std::string postFxPresetToJson(const PostFxParams& params);
//! A shipped name (presets/postfx/NAME.json) or a path to a .json file.
Result<PostFxParams> loadPostFxPreset(const std::string& nameOrPath);
std::vector<std::string> shippedPostFxPresetNames();
//! Markdown table of every preset key (docs/postfx.md).
std::string postFxParameterReference();

}  // namespace flarekit
