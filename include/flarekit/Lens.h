// SPDX-License-Identifier: Apache-2.0
// Lens prescriptions (presets/lenses/NAME.json) and what flarekit computes from them: the
// paraxial focal length, the exact sequential trace of the direct image and of every
// two-reflection ghost (Fresnel and thin-film coatings, dispersion), the flare those ghosts and
// the aperture's diffraction put on an image. Method and sources: docs/lens.md.
//
// Conventions (the file format's): lengths in mm; the optical axis is z and light travels toward
// +z; surfaces are listed from the front; `radius` > 0 puts the centre of curvature on the +z
// side, 0 is flat; `thickness` is the distance to the next surface (the last one's: to the
// sensor plane); `n_d` / `v_d` describe the medium after the surface (absent: air).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"

namespace flarekit {

//! One layer of an anti-reflection stack: its index and physical thickness.
struct CoatingLayer {
    double n = 1.0;            //!< the layer's index (dispersion-free: coating materials vary
                               //!< by under 1% over the visible)
    double thicknessNm = 0.0;  //!< physical thickness
    bool operator==(const CoatingLayer&) const = default;
};

//! An anti-reflection coating: a stack of thin layers, listed from the air side (the
//! lower-index medium of the surface) toward the glass. Empty: uncoated glass. Reflectance is
//! the same from either side of a lossless stack, so one order serves both directions.
struct LensCoating {
    std::vector<CoatingLayer> layers;
    bool present() const { return !layers.empty(); }
    bool operator==(const LensCoating&) const = default;
};

//! The coating designs a prescription can name, each tuned to a design wavelength:
//! - mgf2: one quarter-wave layer of MgF2 (n 1.38), the single coating of the 1950s-70s (Zeiss
//!   T, Asahi's SMC predecessors): least reflective at the design wavelength, rising toward
//!   both ends of the visible, so its ghosts are magenta or purple at a 550 nm design;
//! - broadband: the quarter-half-quarter stack of multi-coated lenses (Lockhart and King, "Three-
//!   layered reflection-reducing coatings", JOSA 1947; MgF2 1.38 / ZrO2 2.05 / CeF3 1.63): two
//!   reflectance minima either side of the design wavelength and a small residual peak at it, so
//!   a surface's ghost takes the design wavelength's colour (green at 520, amber at 590, blue at
//!   470), the mixed greens, ambers and blues of a multi-coated lens;
enum class CoatingDesign { Mgf2, Broadband };
inline constexpr std::string_view kCoatingDesignNames[] = {"mgf2", "broadband"};

//! Layer indices of the designs (Macleod, Thin-Film Optical Filters, 2001, tables of coating
//! materials): MgF2 1.38, CeF3 1.63, ZrO2 2.05.
inline constexpr double kMgF2Index = 1.38, kCeF3Index = 1.63, kZrO2Index = 2.05;
//! The design wavelength of "mgf2" without one: the eye's peak sensitivity, where the classic
//! single coatings were centred.
inline constexpr double kMgF2DesignNm = 550.0;

//! A quarter-wave (optical thickness lambda / 4) layer of index n at `designNm`.
inline CoatingLayer quarterWave(double n, double designNm) {
    return {n, designNm / (4.0 * n)};
}
//! A named design at its design wavelength.
LensCoating coatingDesign(CoatingDesign design, double designNm);
inline LensCoating mgf2Coating(double designNm = kMgF2DesignNm) {
    return coatingDesign(CoatingDesign::Mgf2, designNm);
}

struct LensSurface {
    double radius = 0.0;        //!< mm; 0 = flat
    double thickness = 0.0;     //!< mm to the next surface (the last: to the sensor)
    double nd = 1.0;            //!< index after the surface at the d line (587.56 nm)
    double vd = 0.0;            //!< Abbe number after the surface; 0 = no dispersion (air)
    double semiAperture = 1.0;  //!< mm, clear radius
    bool stop = false;          //!< the aperture stop (flat; never reflects)
    LensCoating coating;
};

inline constexpr Param<LensSurface> kLensSurfaceParams[] = {
    param<&LensSurface::radius>("radius", -kParamUnbounded, kParamUnbounded, "mm",
                                "radius of curvature: > 0 centre on the +z side, 0 flat"),
    param<&LensSurface::thickness>("thickness", -1e5, 1e5, "mm",
                                   "axial distance to the next surface (last: to the sensor)"),
    param<&LensSurface::nd>("n_d", 1.0, 3.0, "", "refractive index after the surface, d line"),
    aboveMin(param<&LensSurface::vd>("v_d", 0.0, 200.0, "",
                                     "Abbe number after the surface (absent: no dispersion)")),
    aboveMin(required(param<&LensSurface::semiAperture>("semi_aperture", 0.0, kParamUnbounded, "mm",
                                                        "clear radius"))),
    param<&LensSurface::stop>("stop", 0, 1, "", "the aperture stop (flat, no radius)"),
};

//! The iris: `blades` n (< 3: a circle), one vertex `rotation_deg` from +x, `roundness` 0 =
//! straight blades (the regular n-gon inscribed in the stop's circle), 1 = the circle.
struct LensAperture {
    int blades = 0;
    double rotationDeg = 0.0;
    double roundness = 0.0;
};

inline constexpr Param<LensAperture> kLensApertureParams[] = {
    param<&LensAperture::blades>("blades", 0, 32, "", "iris blades; fewer than 3: a circle"),
    param<&LensAperture::rotationDeg>("rotation_deg", -360, 360, "deg",
                                      "angle of one vertex from the +x axis"),
    param<&LensAperture::roundness>("roundness", 0, 1, "",
                                    "0 straight blades, 1 a circle, between: bowed blades"),
};

struct LensSensor {
    double width = 36.0;   //!< mm
    double height = 24.0;  //!< mm
};

inline constexpr Param<LensSensor> kLensSensorParams[] = {
    aboveMin(param<&LensSensor::width>("width", 0, 1e4, "mm", "sensor width")),
    aboveMin(param<&LensSensor::height>("height", 0, 1e4, "mm", "sensor height")),
};

//! An artist's look for one ghost, the light reflected at surface `first` and then at `second`
//! (< first): its traced intensity times `gain`, and times `tint` per channel. FlareSim's
//! per-surface gain and tint; the trace is unchanged. A lens file's "ghost_pairs", as
//! {"surfaces": [first, second], "gain": ..., "tint": [r, g, b]}.
struct GhostPairLook {
    int first = 1, second = 0;
    double gain = 1.0;
    Rgb tint{1.f, 1.f, 1.f};
};

inline constexpr Param<GhostPairLook> kGhostPairParams[] = {
    param<&GhostPairLook::gain>("gain", 0, 1e6, "", "multiplies the ghost's traced intensity"),
    param<&GhostPairLook::tint>("tint", 0, 1000, "linear RGB", "multiplies the ghost per channel"),
};

struct Lens {
    std::string name, source;
    double fNumber = 0.0;            //!< the patent's (recorded, not used)
    double patentFocalLength = 0.0;  //!< mm, the value the source states; 0 = not stated
    //! The lens's coating: on every glass-air surface that states none of its own (the file's
    //! top-level "coating"; absent: uncoated).
    LensCoating coating;
    std::vector<LensSurface> surfaces;
    LensAperture aperture;
    LensSensor sensor;
    std::vector<GhostPairLook> ghostPairs;  //!< at most one per pair of surfaces
    int stopIndex() const;
    //! The look of the ghost of surfaces (first, second): gain x tint per channel (1 when the
    //! lens gives that pair none).
    std::array<double, 3> ghostPairFactor(int first, int second) const;
};

//! Lens prescriptions shipped in presets/lenses (names without .json).
std::vector<std::string> lensNames();
//! A prescription by name (presets/lenses) or path, validated: the format's ranges, then the
//! physical checks (one stop, surfaces that do not cross within their clear apertures, clear
//! radii no larger than the sphere, a sensor behind the last surface).
Result<Lens> loadLens(const std::string& nameOrPath);
Result<Lens> parseLens(const std::string& text, const std::string& source);
//! Whether surface `i` takes the lens's own coating when it states none: a glass-air surface
//! that is not the stop (cemented glass-glass surfaces stay bare).
bool takesLensCoating(const Lens& lens, std::size_t i);
//! The lens as the JSON parseLens reads back to the same lens (surfaces, coatings as layers,
//! iris, sensor, ghost pairs): what the studio saves.
std::string lensToJson(const Lens& lens);
//! The checks parseLens makes of a prescription in memory (ranges, one stop, surfaces that do
//! not cross within their clear apertures, the sensor behind the last surface, ghost pairs of
//! real surfaces): an edited lens is refused as its file would be. `what` names it in errors.
Status validateLens(const Lens& lens, const std::string& what = "lens");
//! The lens with its stop scaled so that the paraxial working f-number is `fNumber`; refused
//! when that is wider than the stop as written.
Result<Lens> stopDown(const Lens& lens, double fNumber);

//! Wavelengths (nm) of the three colour channels in RGB mode, and the Fraunhofer lines the
//! dispersion model is fitted at.
inline constexpr std::array<double, 3> kRgbWavelengthsNm = {610.0, 550.0, 465.0};
inline constexpr double kLineF = 486.13, kLineD = 587.56, kLineC = 656.27;

//! n(lambda) of a surface's medium: Cauchy's two terms A + B / lambda^2 fitted so that n(d) =
//! n_d and n(F) - n(C) = (n_d - 1) / v_d; air and v_d = 0 do not disperse.
double refractiveIndex(const LensSurface& s, double lambdaNm);

//! Fresnel reflectance of an interface from index n0 to n2, unpolarised (the mean of s and p),
//! at incidence cosine cos0 in medium n0, through the surface's coating (any stack of layers,
//! by the characteristic-matrix method; none: Fresnel's bare interface).
double interfaceReflectance(double n0, double n2, double cos0, const LensCoating& coating,
                            double lambdaNm);

struct Paraxial {
    double focalLength = 0.0;    //!< effective focal length, mm
    double backFocus = 0.0;      //!< last surface to the paraxial focus, mm
    double entrancePupil = 0.0;  //!< entrance pupil radius, mm
    double fNumber = 0.0;        //!< focalLength / (2 entrancePupil)
};
//! The y-nu paraxial trace of the direct path at `lambdaNm`.
Paraxial paraxial(const Lens& lens, double lambdaNm = kLineD);

//! One ghost (or the direct image) of a distant point source, as `lens ghosts` reports it.
//! Positions are from the d-line trace, on the sensor plane, mm from the axis. A ray that
//! reaches the sensor plane "arrives"; one that arrives inside the sensor's rectangle "lands".
//! Near total internal reflection a few rays leave the last surface grazing the sensor plane
//! and arrive metres away, so the plain centroid of the arriving rays never converges; the
//! centroid of the landing rays and the percentile radii do.
struct GhostFigure {
    int first = -1, second = -1;  //!< reflects at `first`, then at `second` (< first); -1: direct
    //! The centroid of the landing rays; of all arriving rays' median when none lands.
    double centerX = 0, centerY = 0;
    double radius = 0;  //!< centre to the farthest arriving ray
    //! Radii around the landing rays' median (per axis) holding 50% and 90% of them.
    double radius50 = 0, radius90 = 0;
    double onSensor = 0;                //!< landing rays over arriving rays
    std::array<double, 3> intensity{};  //!< share of the light entering the first surface (RGB)
    int rays = 0;                       //!< rays of the d-line trace that arrived
    double beamShare = 0;               //!< arriving rays over the rays entering the lens
};

//! 32,768 landing rays put the centre of every ghost carrying 1% or more of the light within
//! 0.06% of the sensor diagonal of its converged value (the same refinement at 131,072 rays) on
//! every shipped lens at 1, 6 and 12 degrees, where the 64-ray grid alone was up to 1.9% off;
//! 16,384 left one at 0.11% (docs/lens.md).
inline constexpr int kDefaultGhostRays = 32768;

struct GhostQuery {
    double angleXDeg = 0, angleYDeg = 0;  //!< rays travel along (tan X, tan Y, 1)
    int gridSide = 64;                    //!< rays per clear diameter of the first surface
    //! Arriving rays each figure's position is measured from: the beam's cells around the
    //! ghost are traced again more finely until about this many arrive (0: the grid alone).
    int ghostRays = kDefaultGhostRays;
};

struct GhostReport {
    double focalLength = 0;
    GhostFigure direct;
    std::vector<GhostFigure> ghosts;  //!< every two-reflection path, brightest first
};

//! Every two-reflection ghost through the exact tracer; refused when no ray of the direct image
//! or of any ghost reaches the sensor plane at that angle (a light outside the field whose
//! image the lens vignettes away still has its ghosts).
Result<GhostReport> analyseGhosts(const Lens& lens, const GhostQuery& query);

//! The report as `lens ghosts --json` prints it (the contract of docs/lens.md): the lens, the
//! focal length, what each field means, the direct image and every ghost.
std::string ghostReportJson(const std::string& lensName, const GhostReport& report);

//! A point source on the image: pixel position (top-left origin, centres at +0.5) and energy per
//! channel (the sum of the linear pixel values it stands for).
struct LensLight {
    double x = 0, y = 0;
    std::array<double, 3> energy{};
};

//! How bright the ghosts are drawn: `flux` (the default) puts the brightest ghost of the
//! brightest light at kFluxGhostShare of that light's measured energy, the others at their
//! traced ratios to it, so every lens shows its ghost chain on any sun, as the sprite presets'
//! energy model does; `physical` draws each ghost at its traced share of the light (real, and
//! invisible on a clipped sun, whose energy a photograph or HDRI understates by orders of
//! magnitude). Either way `ghost_gain` multiplies the result.
enum class GhostLevel { Flux, Physical };
inline constexpr std::string_view kGhostLevelNames[] = {"flux", "physical"};

//! The brightest ghost's share of its light in `flux` mode: 2%, twice the top of the 0.2-1% the
//! sprite presets' ghosts carry at kReferenceFlux (docs/energy.md): a traced lens spreads its
//! light over dozens of ghosts, most far larger and fainter than its brightest, which at 1%
//! left them under the `subtle` sprite preset's. Calibrated on the blender-data sunrise (a
//! 640x360 crop, the sun of 31,000 at 420,120): the Canon zoom's green rings and the double
//! Gauss's purple ghosts show, the uncoated Petzval's are no longer a white veil.
inline constexpr double kFluxGhostShare = 0.02;

struct LensRenderOptions {
    int ghosts = 66;          //!< the brightest ghosts rendered
    int spectral = 0;         //!< 0: RGB (3 wavelengths); >= 3: that many spectral samples
    int gridSide = 48;        //!< rays per side of each ghost's traced mesh
    double starburst = 0.02;  //!< share of a source's energy drawn as the starburst
    //! Wavelengths the starburst is drawn at, whatever `spectral` is for the ghosts: its
    //! pattern scales with the wavelength, so each one's fringes fall elsewhere along a spike;
    //! 3 (RGB) leaves them as beads, 32 sums them smooth (+0.4 s at 640x360 on 2 cores).
    int starburstSamples = 32;
    double starburstSize = 0.25;  //!< its radius at 550 nm, as a share of the image diagonal
    double glare = 0.01;          //!< share drawn as the veiling glare halo
    GhostLevel ghostLevel = GhostLevel::Flux;
    double ghostGain = 1.0;  //!< multiplies the ghost intensities (after ghostLevel)
    double dirt = 0.0;       //!< dust and scratches on the iris plane (starburst fringes)
    std::uint32_t dirtSeed = 1;
    //! The iris plane's transmission from an image (the user's own dust, scratches or aperture
    //! shape): its luminance, clamped to [0, 1], multiplies the iris, the image stretched over
    //! the stop's diameter (row 0 at the top as seen from the front). Null: none.
    std::shared_ptr<const Image> pupilMask;
    //! Called after each light source with (sources done, sources in all); returning false stops
    //! the render, which then returns an Interrupted error. A SIGINT or SIGTERM caught by
    //! installInterruptHandlers stops it too, within one band of one ghost mesh. Empty: none.
    std::function<bool(int done, int total)> progress;
};

inline constexpr Param<LensRenderOptions> kLensRenderParams[] = {
    param<&LensRenderOptions::ghosts>("ghosts", 0, 4096, "", "the brightest N ghosts drawn"),
    param<&LensRenderOptions::spectral>(
        "spectral", 0, 64, "samples",
        "0: RGB at 610/550/465 nm; N >= 3: N wavelengths over 400-700 nm through CIE 1931"),
    param<&LensRenderOptions::gridSide>("grid", 4, 256, "rays",
                                        "rays per side of each ghost's traced mesh"),
    param<&LensRenderOptions::starburst>("starburst", 0, 1, "",
                                         "share of each source's energy in the starburst"),
    param<&LensRenderOptions::starburstSamples>(
        "starburst_samples", 3, 128, "wavelengths",
        "wavelengths over 400-700 nm the starburst is drawn at (3 shows its fringes as beads)"),
    param<&LensRenderOptions::starburstSize>("starburst_size", 0, 4, "",
                                             "starburst radius at 550 nm / image diagonal"),
    param<&LensRenderOptions::glare>("glare", 0, 1, "",
                                     "share of each source's energy in the glare halo"),
    choice<&LensRenderOptions::ghostLevel>(
        "ghost_level", kGhostLevelNames,
        "\"flux\": the brightest ghost at 2% of its light's measured energy, the rest at their "
        "traced ratios to it; \"physical\": each at its traced share (invisible on a clipped sun)"),
    param<&LensRenderOptions::ghostGain>("ghost_gain", 0, 1e9, "",
                                         "multiplies the ghost intensities (after ghost_level)"),
    param<&LensRenderOptions::dirt>("dirt", 0, 1, "",
                                    "dust and scratches on the iris plane: 0 clean, 1 a badly "
                                    "kept lens; they break the starburst into rainbow fringes"),
    param<&LensRenderOptions::dirtSeed>("dirt_seed", 0, 4294967295.0, "",
                                        "the dirt pattern (same seed, same pattern)"),
};

//! A drawn ghost where the image shows it: the surfaces it reflects at, its centre and size in
//! pixels, its share of the light (RGB).
struct GhostOnImage {
    int first = -1, second = -1;  //!< reflects at `first`, then at `second` (< first)
    double x = 0, y = 0;          //!< centre, pixels from the top-left
    double radius = 0;            //!< pixels holding 90% of its landing rays
    std::array<double, 3> intensity{};
};

//! The `count` brightest ghosts of a light at pixel `light` of a width x height image, as the
//! lens render places that image on the sensor (centred, fitted inside it) and picks its ghosts:
//! what a click on a ghost in the studio names. Brightest first; refused as analyseGhosts is.
Result<std::vector<GhostOnImage>> ghostsOnImage(const Lens& lens, int width, int height,
                                                Point light, int count);

//! The lens as a sprite preset: a glow and (for a bladed iris) its diffraction spikes at the
//! light, then its `ghosts` brightest ghosts traced at one field angle, each a polygon (disc for
//! a round iris) at its traced position on the flare vector, with its size, colour and
//! intensity relative to the others.
Result<Preset> bakeLens(const Lens& lens, int ghosts);

//! The lens drawn in cross-section with the rays of its direct image (on axis and off axis)
//! and of its brightest ghost, above its flare at three field angles; `width` x width 9/16.
Result<Image> renderLensSheet(const Lens& lens, int width);

//! The numbers the lens tools take beside a prescription (ghosts, bake, sheet), described once
//! for the library's checks and the CLI's flags.
struct LensToolOptions {
    int rays = 64;                      //!< GhostQuery::gridSide
    int ghostRays = kDefaultGhostRays;  //!< GhostQuery::ghostRays
    int ghosts = 16;                    //!< bakeLens's ghost count
    int sheetWidth = 1600;              //!< renderLensSheet's width
};

inline constexpr Param<LensToolOptions> kLensToolParams[] = {
    // 1024^2 rays per wavelength and ghost pair: past it the figures stop changing and one
    // report takes minutes.
    param<&LensToolOptions::rays>("rays", 2, 1024, "",
                                  "the beam's rays per clear diameter of the first surface"),
    // 2^20 arriving rays: a ghost's centre stops changing well before it.
    param<&LensToolOptions::ghostRays>(
        "ghost_rays", 0, 1 << 20, "",
        "rays each ghost's position is measured from, traced around it (0: the --rays grid)"),
    // A preset holds kMaxPresetElements; the glow and the spikes take two of them.
    param<&LensToolOptions::ghosts>("ghosts", 1, double(kMaxPresetElements) - 2, "",
                                    "the brightest N ghosts baked"),
    // 320 px keeps the three flare panels legible; 8192 is the widest a texture viewer shows.
    param<&LensToolOptions::sheetWidth>("width", 320, 8192, "px",
                                        "sheet width (height: 9/16 of it)"),
};

//! "--KEY: expected an integer in [MIN, MAX], got V" when `value` is outside kLensToolParams'
//! range for `key`.
Status checkLensToolOption(std::string_view key, int value);

//! The flare's parts over black, linear, on the input's size.
struct LensFlareLayers {
    Image ghosts, starburst, glare;
};

//! The whole flare: the three parts' colour, opaque like each of them.
Image lensFlareSum(const LensFlareLayers& layers);

//! Renders the ghosts, starburst and glare of `lights` (on a `width` x `height` image) through
//! the lens. The pixel-to-field-angle mapping is the sensor's (the image fitted inside it).
Result<LensFlareLayers> renderLensFlare(const Lens& lens, int width, int height,
                                        const std::vector<LensLight>& lights,
                                        const LensRenderOptions& options);

//! The sources of an image: every pixel at or above `threshold` (linear luminance), merged on a
//! grid of cells `cell` pixels wide, at most `maxSources` (the brightest kept).
std::vector<LensLight> brightSources(const Image& image, double threshold, int cell,
                                     int maxSources);
//! The source at pixel (x, y): the energy of the pixels at or above `threshold` within `radius`
//! pixels of it (zero when there are none).
LensLight sourceAt(const Image& image, double x, double y, double radius, double threshold);

}  // namespace flarekit
