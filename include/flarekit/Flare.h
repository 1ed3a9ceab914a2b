// SPDX-License-Identifier: Apache-2.0
// Sprite lens flares (Michael Tanczos, "The Art of Modeling Lens Flares", 1999): a preset's
// elements placed along the flare vector from the screen centre through the light, composited onto
// a linear-light image.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "flarekit/Elements.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"

namespace flarekit {

//! The sprite preset a job uses when none is named.
inline constexpr const char* kDefaultSpritePreset = "tanczos-classic";

struct Preset {
    std::string name;
    std::string description;
    float intensity = 1.f;  //!< multiplies every element
    std::vector<ElementParams> elements;
    //! Another engine's settings for the whole flare that flarekit cannot draw, as compact
    //! JSON (flarekit/Convert.h): kept so converting back restores them. Empty: none.
    std::string source;
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
//! The preset as JSON that parsePreset reads back to the same preset (the keys that differ from
//! an element's defaults, one element per line).
std::string presetToJson(const Preset& preset);
//! A shipped preset by name (see presetSearchPath) or a JSON file by path.
Result<Preset> loadPreset(const std::string& nameOrPath);
//! Directories searched for shipped presets: $FLAREKIT_PRESET_PATH (colon-separated), then
//! share/flarekit/presets beside the running executable's bin/ (an install at any prefix),
//! then the configured install's, then the source tree's presets/. A preset is found by its
//! file name (NAME.json); its "name" field is the title `flarekit presets` prints.
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

//! Where an edge streak goes for a light at `light` (pixels, top-left origin) in a width x
//! height frame: the nearest point of the frame's border (the light clamped to the frame when
//! outside), along that edge (rotationDeg 0 on the top and bottom edges, 90 on the sides), at
//! weight 1 - smoothstep(0, reach x height, distance from the edge) on either side of it.
struct EdgePlacement {
    Point centre;
    float rotationDeg = 0;
    float weight = 0;
};
EdgePlacement edgeStreakPlacement(Point light, int width, int height, float reach);

struct FlareStats {
    std::size_t elementsDrawn = 0;
    std::size_t pixelsShaded = 0;  //!< pixels evaluated: the cost of the flare
};

//! Composites the preset's flare onto `image` in place, for a light at `light` (may be outside
//! the frame), everything scaled by `intensity`. Work is proportional to the pixels the
//! elements cover, never the whole image per element.
FlareStats renderFlare(Image& image, const Preset& preset, Point light, float intensity);

//! A flare split into the passes a compositor grades separately: each element goes to one layer
//! by its type (glow: Glow; halo: Ring; ghosts: Disc, Polygon, Image; streaks: Streaks, EdgeStreak;
//! starburst: Rays). Only the layers the preset has are made, in this order.
struct FlareLayer {
    std::string name;
    Image image;  //!< linear, over transparent black, unclamped
};
inline constexpr const char* kFlareLayerNames[] = {"glow", "halo", "ghosts", "streaks",
                                                   "starburst"};
//! The layer an element type belongs to (an index into kFlareLayerNames).
int flareLayerOf(ElementType type);
//! Every light's flare rendered layer by layer into width x height images, and their sum, the
//! whole flare (`flare`, what input + flare composites: that sum is exact by construction).
std::vector<FlareLayer> renderFlareLayers(int width, int height, const Preset& preset,
                                          const std::vector<std::pair<Point, float>>& lights,
                                          Image& flare);

//! An estimate of the spike evaluations (the costly inner loop of streaks and rays) of one
//! flare of `preset` in a width x height image: per spike about 2 x its support x its length in
//! pixels, clipped to the frame's diagonal.
double flareSpikeWork(const Preset& preset, int width, int height);
//! Refuses (naming `what` and the worst element) a preset whose flares would take minutes:
//! `flares` flares of flareSpikeWork over kMaxSpikeWork evaluations.
Status checkFlareWork(const Preset& preset, int width, int height, int flares,
                      const std::string& what);
//! 2^32 spike evaluations: ~40 s of CPU (~20 s on 2 cores) at the ~9 ns per evaluation measured
//! for 4,096 rays on a 1280x720 frame (an estimate of 6.1e8, 5.7 s of CPU). Every shipped
//! preset at 8K needs under 1% of it.
inline constexpr double kMaxSpikeWork = 4294967296.0;

// The energy model. A lens spreads a fixed share of the light that enters it into each ghost,
// ring and streak, so a flare's brightness follows the source's flux (its luminance summed
// over its area), not its peak: a 31,000 sun of 4 pixels and a 200,000-pixel clipped white
// disc carry comparable energy, a 4-pixel specular glint almost none. Flux is measured in
// units of the frame height squared (a flux of 1 is display white over an area of H x H
// pixels), so the same light gives the same flare at any resolution. A preset's element
// intensities are its look at kReferenceFlux; docs/energy.md lists each element's share.

//! The flux a preset is designed for: one frame-height squared of display white, the flux of
//! a real HDR sun in a 640x360 frame of a ~70 degree field of view (the blender-data sunrise
//! HDRI: 4 pixels of 31,000, 126,000 in all, 0.97 H^2). A ghost of that preset, a disc of
//! radius 0.05-0.1 H at intensity 0.2-0.35, then carries 0.2-1% of the flux, as the ghosts
//! of real multi-coated lenses do.
inline constexpr double kReferenceFlux = 1.0;

//! The flare intensity for a light of `flux` (sum of linear luminance over its pixels) in an
//! image `height` pixels tall: flux / height^2 / kReferenceFlux, linear like real optics.
float flareScaleForFlux(double flux, int height);

struct LightSearchOptions {
    //! No light unless the peak linear luminance reaches this. 0.5 linear is sRGB code 188: a
    //! light source in an 8-bit photo is near 255, while the brightest pixel of an overcast or
    //! indoor frame without a light is usually well below.
    float minLuminance = 0.5f;
    //! A light's core is the pixels >= nearPeak * its peak; 0.9 keeps a clipped sun's disc and
    //! its hottest halo, not the whole sky.
    float nearPeak = 0.9f;
    //! Most lights to flare, brightest flux first.
    int maxLights = 1;
    //! A light is at least this many times brighter than the ring around it (2 to 4 radii out).
    //! A sun, a lamp or a glint is a peak (HDR suns: 100-10,000x; a clipped sun in an 8-bit
    //! photo: 2-4x its sky); white walls, clouds and shirts are plateaus (1-1.6x).
    float minProminence = 2.f;
    //! Display-referred (8/16-bit) input clips every light at 1.0, so its energy cannot be
    //! measured directly. A lens spreads a light's flux F into veiling glare falling as
    //! F c / r^2, which clips a disc of area pi c F: the clipped area grows in proportion to
    //! the flux, and a clipped pixel stands for 1 / (pi c) of it. 4 (c = 0.08) matches the
    //! blender-data sunrise HDRI against its own 8-bit rendering within a factor of 2.
    float clippedGain = 4.f;
};
inline constexpr Param<LightSearchOptions> kLightSearchParams[] = {
    param<&LightSearchOptions::minLuminance>(
        "light-threshold", 0, 1e6, "linear",
        "--light auto: smallest peak linear luminance that counts as a light"),
    param<&LightSearchOptions::nearPeak>(
        "near-peak", 0, 1, "of the peak",
        "--light auto: a light's core is the pixels at least this fraction of its peak"),
    param<&LightSearchOptions::maxLights>("max-lights", 1, 64, "",
                                          "--light auto: most lights to flare, most flux first"),
    param<&LightSearchOptions::minProminence>(
        "min-prominence", 1, 1e6, "x surroundings",
        "--light auto: a light is this many times brighter than the ring 2-4 radii around it"),
    param<&LightSearchOptions::clippedGain>(
        "clipped-gain", 1, 1e6, "x white",
        "--light auto on 8/16-bit input: assumed brightness of a clipped pixel"),
};

//! One bright region `--light auto` considered.
struct LightCandidate {
    Point position;             //!< luminance-weighted centroid of its pixels
    float radius = 0.f;         //!< sqrt(pixels / pi)
    std::size_t pixels = 0;     //!< size of the connected region
    float peak = 0.f;           //!< its brightest pixel (linear luminance)
    float meanLuminance = 0.f;  //!< mean linear luminance of its pixels (as stored)
    double flux = 0.0;          //!< summed luminance (clipped pixels x clippedGain)
    float prominence = 0.f;     //!< mean luminance / mean luminance of the ring around it
    float compactness = 0.f;    //!< share of its pixels within 1.25 radii of it: 1 for a disc
    float halo = 0.f;           //!< mean luminance just outside it (R+1 to 1.5R+2) / its mean
    //! Scene-referred (HDR) input: the light its aureole carries, summed over the rings around
    //! the region while their mean keeps falling, above the sky level where it stops (already
    //! in `flux`); a hazy or capture-clipped sun carries most of its light there.
    double aureoleFlux = 0.0;
    int aureoleRings = 0;  //!< the rings over which the aureole kept falling
    //! Scene-referred input: its pixels whose largest channel is within 1.5% of the region's
    //! largest, when they are at least 30% of its core (0 otherwise); 9 or more are a plateau, a
    //! light clipped at capture (its flux then counts them at clippedGain x the plateau).
    std::size_t flatTopPixels = 0;
    //! Display-referred input and its peak at the file's white in all three channels.
    bool clipped = false;
    std::size_t whitePixels = 0;  //!< display-referred: its pixels at white in every channel
    float flareScale = 0.f;       //!< flareScaleForFlux(flux)
    bool accepted = false;        //!< convincing as a light source
    int checksPassed = 0;         //!< of the finder's checks, in order, before the one it failed
    std::string verdict;          //!< "light", or why not ("1.3x its surroundings, needs 2x")
};

struct LightSearch {
    float peak = 0.f;              //!< peak linear luminance of the image
    Point peakAt;                  //!< where it is (the first such pixel in raster order)
    bool displayReferred = false;  //!< no channel above 1: 8/16-bit data, lights are clipped
    float frameKey = 0.f;          //!< median linear luminance (HDR lights stand 100x above)
    std::vector<LightCandidate> candidates;  //!< every region considered, brightest peak first
    std::vector<LightCandidate> lights;      //!< the accepted ones, most flux first, <= maxLights
    std::string whyNone;                     //!< when `lights` is empty: one line saying why
};

//! `--light auto`: finds bright regions (each grown from its own peak, so a sun's halo is not
//! a second light) and keeps those convincing as light sources: prominent against the ring
//! around them, compact and clipped where the input is display-referred, with enough flux to
//! show a flare. Bounded work: one luminance pass, a sort of the pixels above minLuminance and
//! flood fills that visit each pixel at most once.
LightSearch findLights(const Image& image, const LightSearchOptions& options = {});

//! The candidate that came closest to being a light: the most of the finder's checks passed,
//! then the most flux (a small sun that is only too faint, not the wide glow around it that
//! fails first); the first such. `candidates` must not be empty.
std::size_t closestCandidate(std::span<const LightCandidate> candidates);

//! The share of a candidate's pixels at the file's white in every channel (8/16-bit data).
inline float whiteShare(const LightCandidate& c) {
    return c.pixels ? float(c.whitePixels) / float(c.pixels) : 0.f;
}

//! A hand-placed light (`--light X,Y`, a track key without an intensity) measured as `--light
//! auto` measures the lights it finds: the region grown from the brightest pixel within 2% of
//! the frame height of `at` (at least 4 px), its flux summed the same way (clipped pixels of
//! 8/16-bit data at clippedGain, HDR down to a quarter of its peak; the region kept within 10% of
//! the frame height of `at`, since nothing judges it) and its flareScale from that flux. Nothing
//! there to measure (a black patch) gives flux 0. Outside the frame it is measured the same way
//! (the pixels within its reach that are in the frame: a sun straddling the edge) and its
//! flareScale faded out smoothly over that reach (1 at the edge, 0 one reach out), so a light
//! walking across the edge never jumps; beyond the reach: flux 0 (`--flux-mode fixed` gives an
//! off-frame light the preset's own look). A region that is one of several of one physical
//! light (a strip's spots, a window's panes: the finder's merge rule) takes the flux of the
//! light findLights makes of them all, so a light placed on it is the light found there. The
//! candidate's `position` is its measured centroid; it is not judged (`accepted` is true: the
//! user placed it).
LightCandidate measureLightAt(const Image& image, Point at, const LightSearchOptions& options = {});

//! Most lights an 8/16-bit frame's highlights are expanded around (kLightSearchParams' largest
//! max-lights).
inline constexpr int kMaxExpandedLights = 64;

//! `--expand-highlights` on the lights of an 8/16-bit frame only: expandHighlights' inverse
//! curve (Tonemap.h), weighed by each pixel's nearness to a light findLights accepts (1 within
//! twice the light's radius plus 4 px, the reach it suppresses as the light's glare, easing to 0
//! at 1.5 times that; the radius taken at most 5% of the frame height, a sun's disc through a
//! 250 mm lens). A bright sky, snow or a white wall, which are no light, stay as they are,
//! so the chain flares the lights and not every plateau near white. Returns the lights found.
LightSearch expandHighlightsAtLights(Image& image, float gain, LightSearchOptions options = {});

//! The preset's flare on every light of `search`, each scaled by its own flux x intensity.
FlareStats flareLights(Image& image, const Preset& preset, const LightSearch& search,
                       float intensity = 1.f);

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
