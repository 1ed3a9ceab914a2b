// SPDX-License-Identifier: Apache-2.0
// The lens-flare job (`flarekit lens render`): a lens prescription's traced flare (ghosts,
// starburst, glare) on an image or every frame of a shot, its lights placed or found, on a
// backend the caller chooses: the CPU here, OpenGL from flarekit/gl/LensBackend.h.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flarekit/Lens.h"
#include "flarekit/Param.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/Job.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

//! Where the lens flare is drawn. Shared by a shot's frames; calls from several threads at once
//! are safe (each makes what it needs).
class LensBackend {
  public:
    virtual ~LensBackend() = default;
    virtual std::string name() const = 0;  //!< "cpu", "gl"
    virtual bool usesGl() const = 0;       //!< one frame at a time
    //! The flare's layers of `lights` through `lens` in a width x height frame; `in` names the
    //! image in errors; `verbose`: timing detail through events.
    virtual Result<LensFlareLayers> render(const Lens& lens, int width, int height,
                                           const std::vector<LensLight>& lights,
                                           const LensRenderOptions& options, const std::string& in,
                                           bool verbose, const JobEvents& events) const = 0;
};
//! The CPU renderer (renderLensFlare).
std::shared_ptr<const LensBackend> cpuLensBackend();

//! Which lights the lens flares.
enum class LensLightMode {
    Brightest,  //!< the brightest region: bright pixels merged over a sixteenth of the diagonal
    All,        //!< every bright area a source, merged on a grid (at most maxSources)
    At,         //!< the light at `LensJobOptions::light`, its energy from the pixels around it
};

struct LensJobOptions {
    std::string lens;  //!< a shipped lens name or a prescription JSON file
    //! A lens held in memory (an editor's, made by loadLens or parseLens), used instead of
    //! reading `lens`, which then only names it in messages.
    std::shared_ptr<const Lens> lensData;
    double fNumber = 0;         //!< > 0: stopped down to this working f-number (paraxial)
    std::string input, output;  //!< images, or frame patterns for a sequence
    //! A multi-part EXR input's part to flare (name or index; empty: the first). The other parts
    //! go to the EXR output unchanged; another output format is refused.
    std::string part;
    LensLightMode lightMode = LensLightMode::Brightest;
    Point light;             //!< LensLightMode::At: pixels from the top-left
    double threshold = 2.0;  //!< linear luminance at which a pixel is a source
    int maxSources = 32;     //!< LensLightMode::All: at most this many
    //! 8/16-bit input: clipped pixels count as this gain x white as sources (1: off).
    double expandGain = 64.0;
    //! Also ghosts, starburst, glare and flare (their sum) as linear EXRs here (for a sequence
    //! DIR/ghosts.1001.exr, ...).
    std::string layersDir;
    //! The iris plane's transmission from an image (luminance 1 clear, 0 opaque), read once into
    //! render.pupilMask for every frame; empty: the render's own mask.
    std::string dirtFile;
    //! The layers also as channels of the EXR output (ghosts.R, ..., flare.B; linear float).
    bool layersInOutput = false;
    std::shared_ptr<const LensBackend> backend = cpuLensBackend();
    //! The display curve for 8/16-bit outputs; nothing: filmic for HDR input, else none.
    std::optional<ToneOperator> tonemap;
    //! The render's settings: ghosts at the flux level (GhostLevel): photographs and HDRIs
    //! clip the sun by orders of magnitude (a real one is ~10^5 x the sky), so its traced share
    //! of the measured energy would not show.
    LensRenderOptions render;
    bool verbose = false;
    ShotOptions shot;
    EncodeSettings encode;  //!< compression of the outputs and layers
};

inline constexpr Param<LensJobOptions> kLensJobParams[] = {
    // Up to f/1000, a pinhole; 0 keeps the prescription's own stop.
    param<&LensJobOptions::fNumber>(
        "f_number", 0, 1000, "",
        "stop the lens down to this working f-number (paraxial; 0: as designed)"),
    // Luminance up to 10^12: a sun in absolute units still has a threshold below it.
    param<&LensJobOptions::threshold>("threshold", 0, 1e12, "",
                                      "linear luminance at which a pixel is a source"),
    // 4096 sources: a night city's every window, each a traced flare of its own.
    param<&LensJobOptions::maxSources>("max_sources", 1, 4096, "",
                                       "--light all: at most N sources"),
    // Up to 10^6 x white: a clipped sun's real share (~10^5 x the sky) with a margin.
    param<&LensJobOptions::expandGain>(
        "expand_highlights", 1, 1e6, "",
        "8/16-bit input: clipped pixels count as GAIN x white as sources"),
};

//! The job's lens: loaded by name or file, stopped down when fNumber > 0.
Result<Lens> openJobLens(const LensJobOptions& options);

//! Runs the job; a summary line per image ("OUT: 1 light(s), flare through LENS ...") and, with
//! many sources, a step per source drawn come through the events.
Result<JobReport> runLensJob(const LensJobOptions& options, const JobEvents& events = {});

}  // namespace flarekit
