// SPDX-License-Identifier: Apache-2.0
// Running a job over a shot: the frames of a pattern (shot.####.exr) or a --frames range
// rendered in one process, several at once within the memory budget, each written atomically,
// so a farm can hand out chunks and retry any of them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/Shot.h"
#include "flarekit/job/Job.h"

namespace flarekit {

//! What every sequence-capable job takes besides its own options.
struct ShotOptions {
    std::string frames;  //!< "A-B[:step]" (a farm chunk); empty: every frame found
    bool skipMissing = false;
    double fps = 24;  //!< the shot's frame rate: time between frames for the temporal filters
};
inline constexpr Param<ShotOptions> kShotParams[] = {
    // 1 to 1000 frames per second: from time-lapse to high-speed footage.
    param<&ShotOptions::fps>("fps", 1, 1000, "frames/s",
                             "the shot's frame rate (the temporal filter's time between frames)"),
};

inline constexpr TextParam<ShotOptions> kShotTextParams[] = {
    text<&ShotOptions::frames>(
        "frames",
        "with a frame pattern (shot.####.exr or shot.%04d.exr) in and out: the frames A-B[:step] "
        "to render (default: every frame found); a farm chunk renders exactly these, each output "
        "bit-identical however the shot is chunked"),
};

//! A single image given with frames or skipMissing: an error saying the input is no pattern.
Status checkSingleImage(const std::string& in, const ShotOptions& options);

struct ShotPlan {
    FramePattern in, out;
    std::vector<int> frames;      //!< to render, ascending
    std::vector<int> shotFrames;  //!< every input frame on disk (the filters look back over them)
    std::string outDir;           //!< where coverage.csv goes
    double fps = 24;
    int width = 0, height = 0;  //!< the first frame's size, which every frame must have
};

//! The frames of `in` to render into `out`, checked before any work: both are patterns, the
//! range's frames exist (or are skipped with skipMissing, which warns naming the gaps), and no
//! output file is one of the inputs (the input pattern and `otherInputs`, such as a matte).
Result<ShotPlan> planShot(const std::string& in, const std::string& out, const ShotOptions& options,
                          const std::vector<FramePattern>& otherInputs = {},
                          const JobEvents& events = {});

struct ShotFrame {
    int frame = 0;
    std::string in, out;
};

//! "." + the frame's number as the input names it ("." + "1001"): the suffix of a frame's layer
//! files, so that each layer is a sequence of its own.
std::string frameSuffix(const ShotPlan& plan, const ShotFrame& frame);

//! Reads the first frame's size into the plan (every frame must have it) and returns how many
//! frames of that size fit in the memory budget at once (each `perFrame`, the process's own
//! fixed cost counted once), at most one per core; 1 for a GL backend.
Result<int> framesInFlight(ShotPlan& plan, const JobMemory& perFrame, bool gl);

//! Where a shot's time went (seconds summed over the frames working at once).
struct ShotSummary {
    int frames = 0, parallel = 1;
    double wallSeconds = 0, readSeconds = 0, effectSeconds = 0, writeSeconds = 0;
};
//! The one-line summary a front end prints: "apply: 12 frames in 1.20 s, ...".
std::string describeShotSummary(const std::string& label, const ShotSummary& summary);

//! Renders every frame of the plan with `render`, `parallel` frames at a time (reading one
//! while another renders and a third is written), reporting progress after each frame. On the
//! first failure no further frame starts; those in flight finish. The error is one line naming
//! the failed frame and the frames written; a cancel gives an Interrupted error naming them.
Result<ShotSummary> runShot(const ShotPlan& plan, int parallel,
                            const std::function<Result<ImageOutput>(const ShotFrame&)>& render,
                            const JobEvents& events = {});

}  // namespace flarekit
