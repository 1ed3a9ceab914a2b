// SPDX-License-Identifier: Apache-2.0
// Running a subcommand over a shot: the frames of a pattern (shot.####.exr) or a --frames range
// rendered in one process, several at once within the memory budget, each written atomically,
// so a farm can hand out chunks and retry any of them. A call on a single file is unchanged.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "Common.h"
#include "flarekit/Shot.h"

namespace flarekit::cli {

//! The options every sequence-capable subcommand adds.
struct ShotArgs {
    std::string frames;  //!< --frames A-B[:step]; empty: every frame found
    bool skipMissing = false;
    double fps = 24;  //!< the shot's frame rate: time between frames for the temporal filter
};
void addShotOptions(CLI::App* cmd, ShotArgs& args);

//! A single image given with --frames or --skip-missing: an error saying the input is no pattern.
Status checkSingleImage(const std::string& in, const ShotArgs& args);

struct ShotPlan {
    FramePattern in, out;
    std::vector<int> frames;      //!< to render, ascending
    std::vector<int> shotFrames;  //!< every input frame on disk (the filters look back over them)
    std::string outDir;           //!< where coverage.csv goes
    double fps = 24;
    int width = 0, height = 0;  //!< the first frame's size, which every frame must have
};

//! The frames of `in` to render into `out`, checked before any work: both are patterns, the
//! range's frames exist (or are skipped with --skip-missing, which names the gaps), and no output
//! file is one of the inputs (`inputs`: the input pattern and any matte pattern).
Result<ShotPlan> planShot(const std::string& in, const std::string& out, const ShotArgs& args,
                          const std::vector<FramePattern>& otherInputs = {});

struct ShotFrame {
    int frame = 0;
    std::string in, out;
};

//! "." + the frame's number as the input names it ("." + "1001"): the suffix of a frame's layer
//! files, so that each layer is a sequence of its own.
std::string frameSuffix(const ShotPlan& plan, const ShotFrame& frame);

//! Renders every frame of the plan with `render`, `parallel` frames at a time (reading one
//! while another renders and a third is written), a progress line per 10% (a bar on a
//! terminal). On the first failure no further frame starts; those in flight finish. Returns the
//! exit code; an error is one line naming the failed frame and the frames written.
int runShot(const ShotPlan& plan, const std::string& label, int parallel,
            const std::function<Result<ImageOutput>(const ShotFrame&)>& render);

//! Adds a frame's read time to the summary runShot prints (readInputImage calls it).
void addReadSeconds(double seconds);

//! Reads the first frame's size into the plan (every frame must have it) and returns how many
//! frames of that size fit in the memory budget at once (each `perFrame`, the process's own
//! fixed cost counted once), at most one per core; 1 for a GL backend.
Result<int> framesInFlight(ShotPlan& plan, const JobMemory& perFrame, bool gl);

}  // namespace flarekit::cli
