// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/ShotRun.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "flarekit/Limits.h"
#include "job/ReadClock.h"

namespace flarekit {

Status checkSingleImage(const std::string& in, const ShotOptions& options) {
    if (options.frames.empty() && !options.skipMissing) return Ok{};
    return invalidInput(std::string(options.frames.empty() ? "--skip-missing" : "--frames") + ": " +
                        in + " is one image, not a frame pattern (shot.####.exr)");
}

Result<ShotPlan> planShot(const std::string& in, const std::string& out, const ShotOptions& options,
                          const std::vector<FramePattern>& otherInputs, const JobEvents& events) {
    if (!isFramePattern(out))
        return invalidInput(out + ": the input is a frame pattern, so the output must be one too " +
                            "(e.g. out.####.exr)");
    auto inPattern = parseFramePattern(in);
    if (!inPattern) return inPattern.error();
    auto outPattern = parseFramePattern(out);
    if (!outPattern) return outPattern.error();
    ShotPlan plan{*inPattern, *outPattern, {}, framesOnDisk(*inPattern), {}, options.fps};
    if (plan.shotFrames.empty()) return invalidInput(in + ": no frame of this pattern exists");
    std::vector<int> wanted = plan.shotFrames;
    if (!options.frames.empty()) {
        auto range = parseFrameRange(options.frames, "--frames");
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
    if (!missing.empty() && !options.skipMissing) {
        return invalidInput(plan.in.path(missing.front()) + ": frame " +
                            std::to_string(missing.front()) + " is missing (" +
                            std::to_string(missing.size()) +
                            " of the range in all); --skip-missing renders the others");
    }
    if (!missing.empty()) events.warn(in + ": skipping missing frames " + describeFrames(missing));
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
    // Appended, not "." + substr: GCC 12 warns falsely (-Wrestrict) on the concatenation.
    std::string suffix(1, '.');
    suffix.append(f.in, plan.in.prefix.size(),
                  f.in.size() - plan.in.prefix.size() - plan.in.suffix.size());
    return suffix;
}

Result<int> framesInFlight(ShotPlan& plan, const JobMemory& perFrame, bool gl) {
    auto loaded = readJobInput(plan.in.path(plan.frames.front()), perFrame);
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

std::string describeShotSummary(const std::string& label, const ShotSummary& s) {
    const double busy = std::max(1e-9, s.readSeconds + s.effectSeconds + s.writeSeconds);
    char line[400];
    std::snprintf(line, sizeof line,
                  "%s: %d frames in %.2f s, %.2f frames/s, %d at once; of the frames' time: read "
                  "%.0f%%, effect %.0f%%, write %.0f%%",
                  label.c_str(), s.frames, s.wallSeconds, s.frames / std::max(s.wallSeconds, 1e-9),
                  s.parallel, 100 * s.readSeconds / busy, 100 * s.effectSeconds / busy,
                  100 * s.writeSeconds / busy);
    return line;
}

namespace {
double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//! A frame's rendered image against the shot's size (a sequence's frames share one size).
Status checkFrameSize(const ShotPlan& plan, const ShotFrame& frame, const Image& image) {
    if (image.width() == plan.width && image.height() == plan.height) return Ok{};
    return invalidInput(frame.in + ": " + std::to_string(image.width()) + "x" +
                        std::to_string(image.height()) + ", but the sequence's frame " +
                        plan.in.path(plan.frames.front()) + " is " + std::to_string(plan.width) +
                        "x" + std::to_string(plan.height) + "; a sequence's frames share one size");
}
}  // namespace

Result<ShotSummary> runShot(const ShotPlan& plan, int parallel,
                            const std::function<Result<ImageOutput>(const ShotFrame&)>& render,
                            const JobEvents& events) {
    const auto start = std::chrono::steady_clock::now();
    (void)job_detail::takeReadSeconds();
    std::atomic<double> renderSeconds{0}, writeSeconds{0};
    const int total = int(plan.frames.size());
    std::atomic<int> next{0};
    std::atomic<bool> stop{false}, cancelled{false};
    std::mutex mutex;  // guards everything below
    std::vector<int> written;
    std::optional<std::pair<int, Error>> failure;  // the first failed frame
    int done = 0;
    auto worker = [&] {
        for (;;) {
            if (stop || cancelled) return;
            if (events.stopRequested()) {
                cancelled = true;
                return;
            }
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
                else if (status = checkFrameSize(plan, frame, result->image); status)
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
            if (events.progress) events.progress(++done, total);
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < std::clamp(parallel, 1, total); ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();
    std::sort(written.begin(), written.end());
    const std::string writtenText =
        written.empty() ? "no frame was written"
                        : std::to_string(written.size()) +
                              " frame(s) written and complete: " + describeFrames(written);
    if (failure) {
        Error e = failure->second;
        e.message =
            "frame " + std::to_string(failure->first) + ": " + e.message + "; " + writtenText;
        return e;
    }
    if (cancelled || events.stopRequested()) return cancelledError(writtenText);
    ShotSummary summary;
    summary.frames = total;
    summary.parallel = std::clamp(parallel, 1, total);
    summary.wallSeconds = secondsSince(start);
    summary.readSeconds = job_detail::takeReadSeconds();
    summary.effectSeconds = std::max(0.0, renderSeconds - summary.readSeconds);
    summary.writeSeconds = writeSeconds;
    return summary;
}

}  // namespace flarekit
