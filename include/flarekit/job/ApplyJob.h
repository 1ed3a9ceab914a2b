// SPDX-License-Identifier: Apache-2.0
// The sprite-flare job (`flarekit apply`): a preset's flare composited onto an image or every
// frame of a shot, in linear light, the light placed, found, tracked or projected per frame,
// dimmed by what hides it, with its passes written as layers when asked.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "flarekit/Flare.h"
#include "flarekit/Param.h"
#include "flarekit/Vec3.h"
#include "flarekit/job/Job.h"
#include "flarekit/job/ShotCoverage.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

//! How strong a placed light's flare is (`--light X,Y`, a light track without intensities).
enum class FluxMode {
    Measured,  //!< measured at the point as `--light auto` measures (measureLightAt)
    Fixed,     //!< the preset's own look (flare scale 1), whatever is there
};
inline constexpr std::string_view kFluxModeNames[] = {"measured", "fixed"};

//! How far outside the frame a placed light may be, in pixels: a million, 250 widths of a 4K
//! frame; a flare's elements from a light farther off than that never reach it, and a typo (a
//! coordinate of 1e38) is said, not drawn as nothing.
inline constexpr double kMaxLightCoordinate = 1e6;
//! `at` within kMaxLightCoordinate: one line naming `option` otherwise.
Status checkLightCoordinates(Point at, const std::string& option);

struct ApplyOptions {
    std::string input;   //!< an image, or a frame pattern (shot.####.exr) for a sequence
    std::string output;  //!< an image, or a frame pattern for a sequence
    std::string preset = kDefaultSpritePreset;  //!< shipped name or a JSON file
    //! A multi-part EXR input's part to flare (name or index; empty: the first). The other parts
    //! go to the EXR output unchanged; another output format is refused.
    std::string part;
    float intensity = 1.f;
    float exposure = 1.f;
    //! Where the light is. `light`: fixed, in pixels from the top-left (pixel centres at +0.5);
    //! `lightTrack`: a track file per frame; `camera` with `lightWorld` (a point) or `sunDir`
    //! (a direction): projected per frame. None of them: found in the image (a sequence follows
    //! one light through the shot).
    std::optional<Point> light;
    //! A placed light's strength: measured there, or fixed (the behaviour before measuring);
    //! `intensity` scales either. A track with intensities and a projected light are not
    //! measured.
    FluxMode fluxMode = FluxMode::Measured;
    std::string lightTrack, camera;
    std::optional<Vec3> lightWorld, sunDir;
    LightSearchOptions lightSearch;
    SampleFormat depth = SampleFormat::Auto;  //!< output samples; Auto: from the extension
    //! The display curve; nothing: filmic for HDR input to an 8/16-bit file, else none (and none
    //! for flareOnly).
    std::optional<ToneOperator> tonemap;
    //! Also the flare over black and its passes as float EXRs in this folder (for a sequence
    //! DIR/flare.1001.exr, ...); the output is then exactly input + flare.
    std::string layersDir;
    bool flareOnly = false;  //!< the flare alone over black instead of the composite
    //! The passes and the whole flare also as channels of the EXR output (glow.R, ..., flare.B;
    //! linear float, one file per frame).
    bool layersInOutput = false;
    std::string writeTrack;  //!< a sequence: the light per frame saved as CSV (merged)
    ShotOptions shot;
    OcclusionOptions occlusion;
    std::shared_ptr<const ColorTransform> color;  //!< null: flarekit's defaults
    EncodeSettings encode;                        //!< compression of the outputs and layers
    bool verbose = false;  //!< detail lines (candidates, flares drawn) through JobEvents::info
};
inline constexpr Param<ApplyOptions> kApplyParams[] = {
    // Up to 1000: a sun's flare on a dim plate; beyond that every element is white.
    param<&ApplyOptions::intensity>("intensity", 0, 1000, "", "flare brightness multiplier"),
    param<&ApplyOptions::exposure>(
        "exposure", 0, 1000, "", "multiplies the image (flare included) before the display curve"),
    choice<&ApplyOptions::fluxMode>(
        "flux_mode", kFluxModeNames,
        "--light X,Y and tracks without intensities: measured (the light's flux there, as --light "
        "auto measures it) or fixed (the preset's own strength)"),
};

//! What an apply job did: for a sequence, where its time went.
struct JobReport {
    bool sequence = false;
    ShotSummary shot;
};

//! Runs the job: every option checked before any work (errors are one line naming the option or
//! file, as the CLI prints them), then the image or each frame written atomically.
Result<JobReport> runApplyJob(const ApplyOptions& options, const JobEvents& events = {});

}  // namespace flarekit
