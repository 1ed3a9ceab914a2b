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

//! An anti-reflection coating: none, the classic single quarter-wave MgF2 layer (n = 1.38 at a
//! 550 nm design wavelength), or any single layer given by its index and thickness.
struct LensCoating {
    double n = 1.0;            //!< the layer's index; 1 with thickness 0 = no coating
    double thicknessNm = 0.0;  //!< physical thickness
    bool present() const { return thicknessNm > 0; }
};

//! MgF2's index (1.38, the value the format names) and its quarter-wave thickness at 550 nm.
inline constexpr double kMgF2Index = 1.38;
inline constexpr double kMgF2DesignNm = 550.0;
inline LensCoating mgf2Coating() {
    return {kMgF2Index, kMgF2DesignNm / (4.0 * kMgF2Index)};
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

struct Lens {
    std::string name, source;
    double fNumber = 0.0;            //!< the patent's (recorded, not used)
    double patentFocalLength = 0.0;  //!< mm, the value the source states; 0 = not stated
    std::vector<LensSurface> surfaces;
    LensAperture aperture;
    LensSensor sensor;
    int stopIndex() const;
};

//! Lens prescriptions shipped in presets/lenses (names without .json).
std::vector<std::string> lensNames();
//! A prescription by name (presets/lenses) or path, validated: the format's ranges, then the
//! physical checks (one stop, surfaces that do not cross within their clear apertures, clear
//! radii no larger than the sphere, a sensor behind the last surface).
Result<Lens> loadLens(const std::string& nameOrPath);
Result<Lens> parseLens(const std::string& text, const std::string& source);
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
//! at incidence cosine cos0 in medium n0, through an optional single-layer coating.
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
struct GhostFigure {
    int first = -1, second = -1;  //!< reflects at `first`, then at `second` (< first); -1: direct
    double centerX = 0, centerY = 0;    //!< mm, centroid of the rays reaching the sensor (d line)
    double radius = 0;                  //!< mm, centroid to the farthest of those rays
    std::array<double, 3> intensity{};  //!< share of the light entering the first surface (RGB)
    int rays = 0;                       //!< rays of the d-line trace that reached the sensor
};

struct GhostQuery {
    double angleXDeg = 0, angleYDeg = 0;  //!< rays travel along (tan X, tan Y, 1)
    int gridSide = 64;                    //!< rays per side over the first clear aperture
};

struct GhostReport {
    double focalLength = 0;
    GhostFigure direct;
    std::vector<GhostFigure> ghosts;  //!< every two-reflection path, brightest first
};

//! Every two-reflection ghost through the exact tracer; refused when no ray of the direct
//! image reaches the sensor at that angle.
Result<GhostReport> analyseGhosts(const Lens& lens, const GhostQuery& query);

//! A point source on the image: pixel position (top-left origin, centres at +0.5) and energy per
//! channel (the sum of the linear pixel values it stands for).
struct LensLight {
    double x = 0, y = 0;
    std::array<double, 3> energy{};
};

struct LensRenderOptions {
    int ghosts = 66;              //!< the brightest ghosts rendered
    int spectral = 0;             //!< 0: RGB (3 wavelengths); >= 3: that many spectral samples
    int gridSide = 48;            //!< rays per side of each ghost's traced mesh
    double starburst = 0.02;      //!< share of a source's energy drawn as the starburst
    double starburstSize = 0.25;  //!< its radius at 550 nm, as a share of the image diagonal
    double glare = 0.01;          //!< share drawn as the veiling glare halo
    double ghostGain = 1.0;       //!< multiplies the physical ghost intensities
    double dirt = 0.0;            //!< dust and scratches on the iris plane (starburst fringes)
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
    param<&LensRenderOptions::starburstSize>("starburst_size", 0, 4, "",
                                             "starburst radius at 550 nm / image diagonal"),
    param<&LensRenderOptions::glare>("glare", 0, 1, "",
                                     "share of each source's energy in the glare halo"),
    param<&LensRenderOptions::ghostGain>("ghost_gain", 0, 1e9, "",
                                         "multiplies the physical ghost intensities"),
    param<&LensRenderOptions::dirt>("dirt", 0, 1, "",
                                    "dust and scratches on the iris plane: 0 clean, 1 a badly "
                                    "kept lens; they break the starburst into rainbow fringes"),
    param<&LensRenderOptions::dirtSeed>("dirt_seed", 0, 4294967295.0, "",
                                        "the dirt pattern (same seed, same pattern)"),
};

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
    int rays = 64;          //!< GhostQuery::gridSide
    int ghosts = 16;        //!< bakeLens's ghost count
    int sheetWidth = 1600;  //!< renderLensSheet's width
};

inline constexpr Param<LensToolOptions> kLensToolParams[] = {
    // 1024^2 rays per wavelength and ghost pair: past it the figures stop changing and one
    // report takes minutes.
    param<&LensToolOptions::rays>("rays", 2, 1024, "",
                                  "rays per side over the first clear aperture"),
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
