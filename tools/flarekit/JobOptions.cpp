// SPDX-License-Identifier: Apache-2.0
#include "JobOptions.h"

#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <optional>
#include <span>

#include "Common.h"
#include "ParamOptions.h"
#include "core/Interrupt.h"

namespace flarekit::cli {

void addShotOptions(CLI::App* cmd, ShotOptions& options) {
    addTextOptions<ShotOptions>(cmd, kShotTextParams, options);
    cmd->add_flag("--skip-missing", options.skipMissing,
                  "render the frames that exist and list the gaps, instead of stopping at the "
                  "first missing frame");
    addParamOptions<ShotOptions>(cmd, kShotParams, options);
}

void addOcclusionOptions(CLI::App* cmd, OcclusionOptions& options) {
    addTextOptions<OcclusionOptions>(cmd, kOcclusionTextParams, options);
    cmd->add_option("--light-depth", options.lightDepth,
                    "the light's distance, in the depth pass's units");
    addParamOptions<OcclusionOptions>(cmd, kOcclusionParams, options);
    addParamOptions<TemporalParams>(cmd, std::span(kTemporalParams).first(3), options.temporal);
}

void addColorOptions(CLI::App* cmd, OcioSettings& settings) {
    addTextOptions<OcioSettings>(cmd, kOcioTextParams, settings);
}

void addPartOption(CLI::App* cmd, std::string& part) {
    cmd->add_option("--part", part,
                    "a multi-part EXR input (stereo views, comp layers): the part to flare, by "
                    "name, or by index when no part has that name (#N: always the index; "
                    "default: the first); every other part goes to the EXR output unchanged");
}

void addLensChoiceOptions(CLI::App* cmd, LensJobOptions& target) {
    cmd->add_option("lens", target.lens, "lens prescription: a shipped name or a JSON file")
        ->required();
    addParamOptions<LensJobOptions>(cmd, std::span(kLensJobParams).first(1), target);
}

void addLayersInOutputOption(CLI::App* cmd, bool& layersInOutput) {
    cmd->add_flag("--layers-in-output", layersInOutput,
                  "also write the passes as named channels of the EXR output (flare.R, ghosts.R, "
                  "...; linear float), one file per frame as compositing packages expect");
}

CliRun::CliRun(std::string label)
    : m_label(std::move(label)), m_progress(std::make_shared<Progress>(m_label, 1)) {
    m_events.warning = [](const std::string& line) { warn(line); };
    // Detail lines from several frames at once: one whole line at a time.
    auto stdoutMutex = std::make_shared<std::mutex>();
    m_events.info = [stdoutMutex](const std::string& line) {
        std::lock_guard lock(*stdoutMutex);
        std::printf("%s\n", printable(line).c_str());
    };
    m_events.progress = [progress = m_progress](int done, int total) {
        progress->setTotal(total);
        progress->update(done);
    };
    // Steps inside an image (a lens render's sources, which take minutes): a bar on a terminal,
    // otherwise (logs, a farm) a line per step.
    struct StepBar {
        std::mutex mutex;
        std::optional<Progress> bar;
    };
    m_events.steps = [label = m_label, state = std::make_shared<StepBar>(),
                      tty = isatty(fileno(stderr)) == 1](
                         const std::string& image, const std::string& what, int done, int total) {
        std::lock_guard lock(state->mutex);
        if (!tty) {
            std::fprintf(stderr, "%s: %s: %s %d of %d drawn\n", label.c_str(),
                         printable(image).c_str(), what.c_str(), done, total);
            return;
        }
        if (!state->bar) state->bar.emplace(label, total);
        state->bar->update(done);
        if (done == total) {
            state->bar->finish();
            state->bar.reset();
        }
    };
    m_events.cancelled = [] { return interrupted(); };
}

int CliRun::finish(const Status& status) {
    m_progress->finish();
    return status ? kExitOk : report(status.error());
}

int CliRun::finish(const Result<ShotSummary>& summary) {
    m_progress->finish();
    if (!summary) return report(summary.error());
    std::fprintf(stderr, "%s\n", describeShotSummary(m_label, *summary).c_str());
    return kExitOk;
}

int CliRun::finish(const Result<JobReport>& result) {
    if (!result) {
        m_progress->finish();
        return report(result.error());
    }
    if (!result->sequence) return kExitOk;
    return finish(Result<ShotSummary>(result->shot));
}

}  // namespace flarekit::cli
