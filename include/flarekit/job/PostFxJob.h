// SPDX-License-Identifier: Apache-2.0
// The post-process flare job (`flarekit postfx`): the image-based chain (Killzone 2 / Kawase
// ghosts, bloom, halo, streaks, starburst, dirt) on an image or every frame of a shot, on a
// backend the caller chooses: the CPU here, OpenGL from flarekit/gl/PostFxBackend.h.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "flarekit/Param.h"
#include "flarekit/PostFx.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/Job.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

//! The preset a postfx job uses when none is named.
inline constexpr const char* kDefaultPostFxPreset = "photo";

//! Where the chain runs. A backend is shared by a shot's frames; each call makes its own chain,
//! so calls from several threads at once are safe.
class PostFxBackend {
  public:
    virtual ~PostFxBackend() = default;
    virtual std::string name() const = 0;  //!< "cpu", "gl"
    virtual bool usesGl() const = 0;       //!< one frame at a time, GL's memory figures
    //! Runs the chain `repeat` times on `image` (buffers kept, as in a video). `overwrite`: the
    //! caller has no further use for `image`, which may become the result. `warmSeconds`: the
    //! mean time of the runs after the first (0 for one run). `in` names the image in errors.
    virtual Result<PostFxResult> run(Image& image, bool overwrite, const PostFxParams& params,
                                     const PostFxOptions& options, int repeat, double& warmSeconds,
                                     const std::string& in, const JobEvents& events) const = 0;
};
//! The CPU chain (CpuPostFx).
std::shared_ptr<const PostFxBackend> cpuPostFxBackend();

//! How a GPU backend moves the image to and from the GPU (`--gl-transfer`; gl::GlTransfer in
//! this order): named here so that a front end built without GL still takes the flag.
inline constexpr std::string_view kGpuTransferNames[] = {"auto", "half", "float"};

//! --expand-highlights' gain (PostFxJobOptions::expandHighlights), described once.
struct ExpandHighlights {
    float gain = 4;  //!< the flag without a value
};

inline constexpr Param<ExpandHighlights> kExpandHighlightsParams[] = {
    // 10^4 x white: a clipped sun's core in an 8-bit photo is some 10^4-10^5 x the sky it was
    // clipped to, and past this the chain's ghosts of a lamp swamp the frame.
    param<&ExpandHighlights::gain>("expand_highlights", 1, 1e4, "",
                                   "8/16-bit input: clipped pixels count as GAIN x white"),
};

//! "--expand-highlights: expected a gain in [1, 10000], got 'TEXT'" unless `gain` fits.
Status checkExpandHighlights(double gain, const std::string& text);

//! The chain's layers as files and channels (with "final", the result, in a layers folder).
inline constexpr const char* kPostFxLayerNames[] = {"bloom", "ghosts", "halo", "streaks", "lens"};

struct PostFxJobOptions {
    std::string input, output;                  //!< images, or frame patterns for a sequence
    std::string preset = kDefaultPostFxPreset;  //!< shipped name or a JSON file
    //! A preset held in memory (an editor's), used instead of reading `preset`, which then only
    //! names it in messages. Checked with validatePostFxParams.
    std::shared_ptr<const PostFxParams> presetParams;
    //! A multi-part EXR input's part to flare (name or index; empty: the first). The other parts
    //! go to the EXR output unchanged; another output format is refused.
    std::string part;
    std::shared_ptr<const PostFxBackend> backend = cpuPostFxBackend();
    //! The display curve; nothing: the preset's (filmic for HDR input to an 8/16-bit file when
    //! the preset has none).
    std::optional<ToneOperator> tonemap;
    std::optional<float> exposure, threshold, knee;  //!< overrides of the preset's
    //! 8/16-bit input: clipped pixels expanded to this gain x white before the chain
    //! (kExpandHighlightsParams), so the lights of an 8-bit photo flare; the output keeps the
    //! original pixels.
    std::optional<float> expandHighlights;
    std::string layersDir;  //!< also bloom, ghosts, halo, streaks, lens, final as EXRs here
    //! The layers also as channels of the EXR output (bloom.R, ..., lens.B; linear float).
    bool layersInOutput = false;
    int repeat = 1;        //!< benchmarking: the chain N times, the mean warm time reported
    bool verbose = false;  //!< each pass's time through JobEvents::info
    ShotOptions shot;
    std::shared_ptr<const ColorTransform> color;
    EncodeSettings encode;  //!< compression of the outputs and layers
};
inline constexpr Param<PostFxJobOptions> kPostFxJobParams[] = {
    // Up to 1000 runs: enough for a stable mean, bounded in time.
    param<&PostFxJobOptions::repeat>(
        "repeat", 1, 1000, "runs",
        "run the chain N times and print the mean time of the warm runs (benchmarking)"),
};

Result<JobReport> runPostFxJob(const PostFxJobOptions& options, const JobEvents& events = {});

}  // namespace flarekit
