// SPDX-License-Identifier: Apache-2.0
// flarekit demo: the library's demo job (flarekit/gl/DemoJob.h), the built-in drive rendered to
// PNG frames, a coverage log and a strip of six frames, and with ffmpeg installed an MP4.
#include <cstdio>
#include <filesystem>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "flarekit/Demo.h"
#include "flarekit/gl/GpuVisibility.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/DemoJob.h"
#endif

namespace flarekit::cli {

namespace {

struct DemoArgs {
    std::string outDir, size = "1280x720", preset = kDefaultSpritePreset;
    DemoSettings settings;
    bool noVideo = false;
    bool noFrames = false;  //!< render and time the drive, write nothing (the render stage alone)
};

#if FLAREKIT_HAS_GL
int runDemo(const DemoArgs& a) {
    const auto size = parseSize(a.size);
    if (!size)
        return report(
            invalidInput("--size: expected WIDTHxHEIGHT, e.g. 1280x720, got '" + a.size + "'"));
    gl::DemoJobOptions o;
    o.outDir = a.outDir;
    o.settings = a.settings;
    o.settings.width = size->first;
    o.settings.height = size->second;
    o.preset = a.preset;
    o.noFrames = a.noFrames;
    o.reserveVideo = !a.noVideo;
    o.encode = encodeSettings();
    CliRun run("demo");
    auto r = gl::runDemoJob(o, run.events());
    if (!r) return run.finish(Result<ShotSummary>(r.error()));
    run.finish(Status(Ok{}));
    std::printf(
        "demo: per frame %.1f ms render, %.1f ms visibility (%s), %.1f ms flare + tone map%s\n",
        r->renderMs, r->visibilityMs, a.settings.method.c_str(), r->flareMs,
        a.noFrames ? " (--no-frames: nothing written)" : "");
    if (a.noFrames) return kExitOk;
    const std::string dir = std::filesystem::path(a.outDir).string() + "/";
    std::printf("demo: frames %s .. %s, log %scoverage.csv, strip %sstrip.png\n",
                r->framePath(o, 0).c_str(), r->framePath(o, r->frames - 1).c_str(), dir.c_str(),
                dir.c_str());
    if (a.noVideo) return kExitOk;
    auto video = gl::encodeDemoVideo(o, *r);
    if (!video) return report(video.error());
    if (*video)
        std::printf("demo: video %sdemo.mp4 (%.3g fps)\n", dir.c_str(), o.settings.fps);
    else
        warn("ffmpeg is not installed: no MP4 (the PNG frames are written)");
    return kExitOk;
}
#else
int runDemo(const DemoArgs&) {
    return report(builtWithoutGl("demo"));
}
#endif
}  // namespace

void addDemoCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<DemoArgs>();
    CLI::App* cmd = app.add_subcommand("demo",
                                       "Render the built-in drive (trees, buildings, tunnel, turn) "
                                       "with an occlusion-aware sun flare");
    cmd->add_option("-o,--output", args->outDir, "output directory (created if missing)")
        ->required();
    addParamOption<DemoSettings>(cmd, kDemoParams, "frames", args->settings);
    addParamOption<DemoSettings>(cmd, kDemoParams, "fps", args->settings);
    cmd->add_option("--size", args->size, "frame size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option(
           "--method", args->settings.method,
           "visibility method, one of " + visibilityMethodList() +
               " (raycast: CPU flare; the others: flare, smoothing and tone map on the GPU)")
        ->capture_default_str();
    cmd->add_option("--preset", args->preset, "sprite flare preset (name or JSON file)")
        ->capture_default_str();
    cmd->add_flag(
        "--conditional-render", args->settings.conditionalRender,
        "with --method query: draw the flare under glBeginConditionalRender on the sun's query");
    addParamOption<DemoSettings>(cmd, kDemoParams, "samples", args->settings);
    addParamOption<DemoSettings>(cmd, kDemoParams, "msaa", args->settings);
    addParamOptions<TemporalParams>(cmd, kTemporalParams, args->settings.temporal);
    cmd->add_flag("--no-video", args->noVideo, "skip the MP4 even when ffmpeg is installed");
    cmd->add_flag("--no-frames", args->noFrames,
                  "render and time the drive but write nothing (the render stage's cost without "
                  "the frame writer beside it)");
    cmd->callback([args, &exitCode] { exitCode = runDemo(*args); });
}

}  // namespace flarekit::cli
