// SPDX-License-Identifier: Apache-2.0
#include "ShotRun.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "ParamOptions.h"
#include "Progress.h"
#include "core/Interrupt.h"
#include "flarekit/Limits.h"

namespace flarekit::cli {

void addShotOptions(CLI::App* cmd, ShotArgs& args) {
    cmd->add_option("--frames", args.frames,
                    "with a frame pattern (shot.####.exr or shot.%04d.exr) in and out: the frames "
                    "A-B[:step] to render (default: every frame found); a farm chunk renders "
                    "exactly these, each output bit-identical however the shot is chunked");
    cmd->add_flag("--skip-missing", args.skipMissing,
                  "render the frames that exist and list the gaps, instead of stopping at the "
                  "first missing frame");
    cmd->add_option("--fps", args.fps,
                    "the shot's frame rate (the temporal filter's time between frames)")
        ->check(CLI::Range(1.0, 1000.0))
        ->capture_default_str();
}

Status checkSingleImage(const std::string& in, const ShotArgs& args) {
    if (args.frames.empty() && !args.skipMissing) return Ok{};
    return invalidInput(std::string(args.frames.empty() ? "--skip-missing" : "--frames") + ": " +
                        in + " is one image, not a frame pattern (shot.####.exr)");
}

Result<ShotPlan> planShot(const std::string& in, const std::string& out, const ShotArgs& args,
                          const std::vector<FramePattern>& otherInputs) {
    if (!isFramePattern(out))
        return invalidInput(out + ": the input is a frame pattern, so the output must be one too " +
                            "(e.g. out.####.exr)");
    auto inPattern = parseFramePattern(in);
    if (!inPattern) return inPattern.error();
    auto outPattern = parseFramePattern(out);
    if (!outPattern) return outPattern.error();
    ShotPlan plan{*inPattern, *outPattern, {}, framesOnDisk(*inPattern), {}, args.fps};
    if (plan.shotFrames.empty()) return invalidInput(in + ": no frame of this pattern exists");
    std::vector<int> wanted = plan.shotFrames;
    if (!args.frames.empty()) {
        auto range = parseFrameRange(args.frames, "--frames");
        if (!range) return range.error();
        wanted = range->frames();
    }
    std::vector<int> missing;
    for (int f : wanted) {
        if (std::binary_search(plan.shotFrames.begin(), plan.shotFrames.end(), f))
            plan.frames.push_back(f);
        else
            missing.push_back(f);
    }
    if (!missing.empty() && !args.skipMissing) {
        return invalidInput(plan.in.path(missing.front()) + ": frame " +
                            std::to_string(missing.front()) + " is missing (" +
                            std::to_string(missing.size()) +
                            " of the range in all); --skip-missing renders the others");
    }
    if (!missing.empty()) warn(in + ": skipping missing frames " + describeFrames(missing));
    if (plan.frames.empty()) return invalidInput(in + ": no frame of the range exists");
    // An output that is one of the inputs would be replaced before it is read.
    namespace fs = std::filesystem;
    std::vector<FramePattern> inputs = otherInputs;
    inputs.push_back(plan.in);
    for (int f : plan.frames) {
        const std::string target = plan.out.path(f);
        for (const FramePattern& input : inputs) {
            std::error_code ec;
            const std::string source = input.path(f);
            if (source == target || (fs::exists(target, ec) && fs::equivalent(source, target, ec)))
                return invalidInput(out + ": frame " + std::to_string(f) +
                                    " would overwrite its input " + source +
                                    "; write the output elsewhere");
        }
    }
    plan.outDir = fs::path(plan.out.path(plan.frames.front())).parent_path().string();
    if (plan.outDir.empty()) plan.outDir = ".";
    if (Status s = checkOutputPath(plan.out.path(plan.frames.front())); !s) return s.error();
    return plan;
}

std::string frameSuffix(const ShotPlan& plan, const ShotFrame& f) {
    return "." + f.in.substr(plan.in.prefix.size(),
                             f.in.size() - plan.in.prefix.size() - plan.in.suffix.size());
}

Result<int> framesInFlight(ShotPlan& plan, const JobMemory& perFrame, bool gl) {
    auto loaded = readInputImage(plan.in.path(plan.frames.front()), perFrame);
    if (!loaded) return loaded.error();
    plan.width = loaded->image.width();
    plan.height = loaded->image.height();
    if (gl) return 1;  // one GL context renders one frame at a time
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const double frameBytes = perFrame.bytesPerPixel * double(loaded->image.pixelCount());
    const double budget = double(resourceLimits().maxMemoryBytes) - perFrame.fixedBytes;
    const int fit = frameBytes > 0 ? int(budget / frameBytes) : cores;
    return std::clamp(fit, 1, cores);
}

namespace {
//! Seconds the frames spent reading their input (readInputImage adds to it), summed over the
//! threads: the read share of the summary line.
std::atomic<double> g_readSeconds{0};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

void addReadSeconds(double seconds) {
    g_readSeconds += seconds;
}

int runShot(const ShotPlan& plan, const std::string& label, int parallel,
            const std::function<Result<ImageOutput>(const ShotFrame&)>& render) {
    const auto start = std::chrono::steady_clock::now();
    g_readSeconds = 0;
    std::atomic<double> renderSeconds{0}, writeSeconds{0};
    const int total = int(plan.frames.size());
    std::atomic<int> next{0};
    std::atomic<bool> stop{false};
    std::mutex mutex;  // guards everything below
    std::vector<int> written;
    std::optional<std::pair<int, Error>> failure;  // the first failed frame
    int done = 0;
    Progress progress(label, total);
    auto worker = [&] {
        for (;;) {
            if (stop || interrupted()) return;
            const int i = next++;
            if (i >= total) return;
            const int f = plan.frames[std::size_t(i)];
            const ShotFrame frame{f, plan.in.path(f), plan.out.path(f)};
            Status status = checkOutputPath(frame.out);
            if (status) {
                const auto renderStart = std::chrono::steady_clock::now();
                auto result = render(frame);
                renderSeconds += secondsSince(renderStart);
                const auto writeStart = std::chrono::steady_clock::now();
                if (!result)
                    status = result.error();
                else if (result->image.width() != plan.width ||
                         result->image.height() != plan.height)
                    status = invalidInput(
                        frame.in + ": " + std::to_string(result->image.width()) + "x" +
                        std::to_string(result->image.height()) + ", but the sequence's frame " +
                        plan.in.path(plan.frames.front()) + " is " + std::to_string(plan.width) +
                        "x" + std::to_string(plan.height) + "; a sequence's frames share one size");
                else
                    status = writeImage(frame.out, result->image, result->options);
                writeSeconds += secondsSince(writeStart);
            }
            std::lock_guard lock(mutex);
            if (!status) {
                if (!failure || f < failure->first) failure.emplace(f, status.error());
                stop = true;
                continue;
            }
            written.push_back(f);
            progress.update(++done);
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < std::clamp(parallel, 1, total); ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();
    progress.finish();
    std::sort(written.begin(), written.end());
    const std::string writtenText =
        written.empty() ? "no frame was written"
                        : std::to_string(written.size()) +
                              " frame(s) written and complete: " + describeFrames(written);
    if (failure) {
        Error e = failure->second;
        e.message =
            "frame " + std::to_string(failure->first) + ": " + e.message + "; " + writtenText;
        return report(e);
    }
    if (interrupted()) return report(interruptedError(writtenText));
    // Where the frames' time went (summed over the threads working at once).
    const double wall = secondsSince(start), read = g_readSeconds,
                 effect = std::max(0.0, renderSeconds - read), write = writeSeconds;
    const double busy = std::max(1e-9, read + effect + write);
    std::fprintf(stderr,
                 "%s: %d frames in %.2f s, %.2f frames/s, %d at once; of the frames' time: read "
                 "%.0f%%, effect %.0f%%, write %.0f%%\n",
                 label.c_str(), total, wall, total / std::max(wall, 1e-9),
                 std::clamp(parallel, 1, total), 100 * read / busy, 100 * effect / busy,
                 100 * write / busy);
    return kExitOk;
}

}  // namespace flarekit::cli
