// SPDX-License-Identifier: Apache-2.0
// The CLI side of the library's jobs (flarekit/job/): the options every job shares as flags
// (shot, occlusion, colour spaces), and a run's events shown on the terminal: warnings as
// "flarekit: warning: ..." lines, detail on stdout, progress as a bar or a line per 10%,
// cancellation by SIGINT/SIGTERM.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "Progress.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/ShotCoverage.h"
#include "flarekit/job/ShotRun.h"
#include "flarekit/ocio/OcioTransform.h"

namespace flarekit::cli {

void addShotOptions(CLI::App* cmd, ShotOptions& options);
void addOcclusionOptions(CLI::App* cmd, OcclusionOptions& options);
void addColorOptions(CLI::App* cmd, OcioSettings& settings);
//! --part NAME|INDEX: a multi-part EXR's part to flare.
void addPartOption(CLI::App* cmd, std::string& part);
//! The lens positional and --f-number, as every `lens` subcommand takes them.
void addLensChoiceOptions(CLI::App* cmd, LensJobOptions& target);
//! --layers-in-output: the passes as named channels of the EXR output.
void addLayersInOutputOption(CLI::App* cmd, bool& layersInOutput);

//! One job run from the command line: its events, and its result as an exit code.
class CliRun {
  public:
    explicit CliRun(std::string label);
    const JobEvents& events() const { return m_events; }
    //! Exit code of a finished job: its error as one line, or for a sequence the summary line.
    int finish(const Status& status);
    int finish(const Result<ShotSummary>& summary);
    int finish(const Result<JobReport>& report);

  private:
    std::string m_label;
    std::shared_ptr<Progress> m_progress;
    JobEvents m_events;
};

}  // namespace flarekit::cli
