// SPDX-License-Identifier: Apache-2.0
// flarekit postfx: the library's image-based flare job (flarekit/job/PostFxJob.h) from the
// command line, on the CPU or OpenGL.
#include <cmath>
#include <cstdlib>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "flarekit/job/PostFxJob.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/PostFxBackend.h"
#endif

namespace flarekit::cli {

namespace {
//! The words of the command line that the library takes typed.
struct PostFxText {
    std::string backend = "cpu", tonemap = "preset", glTransfer = "auto";
    //! --expand-highlights[=GAIN], as given ("" off): a flag with an optional value, which
    //! CLI11 would round to an integer if it were bound to a number.
    std::string expandHighlights;
    OcioSettings color;
};

Status readText(const PostFxText& t, PostFxJobOptions& o) {
    o.tonemap = toneOperatorNamed(t.tonemap);
    if (!t.expandHighlights.empty()) {
        char* end = nullptr;
        const double g = std::strtod(t.expandHighlights.c_str(), &end);
        const bool number = end != t.expandHighlights.c_str() && *end == '\0';
        if (Status s = checkExpandHighlights(number ? g : NAN, t.expandHighlights); !s)
            return s.error();
        o.expandHighlights = float(g);
    }
    if (t.backend == "gl") {
#if FLAREKIT_HAS_GL
        o.backend =
            gl::glPostFxBackend(gl::GlTransfer(choiceIndex(kGpuTransferNames, t.glTransfer)));
#else
        return builtWithoutGl("postfx --backend gl");
#endif
    }
    auto color = createOcioTransform(t.color);
    if (!color) return color.error();
    o.color = *color;
    return Ok{};
}

int runPostFx(const PostFxText& text, PostFxJobOptions options) {
    if (Status s = readText(text, options); !s) return report(s.error());
    options.encode = encodeSettings();
    CliRun run("postfx");
    return run.finish(runPostFxJob(options, run.events()));
}
}  // namespace

void addPostFxCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<PostFxJobOptions>();
    auto text = std::make_shared<PostFxText>();
    CLI::App* cmd = app.add_subcommand("postfx",
                                       "Image-based lens flare (Killzone 2 / Kawase ghosts, bloom, "
                                       "halo, streaks, dirt) on any image");
    cmd->add_option("input", args->input,
                    "input image (EXR kept linear; 8-bit files are sRGB-decoded; grey and "
                    "grey+alpha promoted), or a frame pattern (shot.####.exr) for a sequence")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "output image; format and bit depth follow the extension")
        ->required();
    cmd->add_option(
           "--preset", args->preset,
           "shipped post-process preset (killzone2, modern, anamorphic, subtle) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--backend", text->backend, "cpu, or gl (OpenGL 4.5 through headless EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    cmd->add_option("--gl-transfer", text->glTransfer,
                    "--backend gl: how the image moves to and from the GPU: half (half floats "
                    "where nothing is lost: a half EXR in, a half EXR out), float, or auto (half "
                    "on a GPU, float on llvmpipe, where halves cost a conversion and save nothing)")
        ->check(CLI::IsMember(choiceNames(kGpuTransferNames)))
        ->capture_default_str();
    cmd->add_option(
        "--save-layers", args->layersDir,
        "also write bloom, ghosts, halo, streaks, lens and final (linear EXR) into DIR (for a "
        "sequence, into DIR/FRAME/)");
    cmd->add_option("--tonemap", text->tonemap,
                    "display curve: preset (the preset's; filmic for HDR input to an 8/16-bit file "
                    "when the preset has none), none, aces, filmic")
        ->check(CLI::IsMember(toneChoices({"preset"})))
        ->capture_default_str();
    addParamOverride(cmd, "--exposure", *findParam<ToneParams>(kToneParams, "exposure"),
                     args->exposure, "the preset's");
    addParamOverride(cmd, "--threshold", *findParam<BrightParams>(kBrightParams, "threshold"),
                     args->threshold, "the preset's, 1 for HDR; 8-bit photos clip at 1, try 0.9");
    addParamOverride(cmd, "--knee", *findParam<BrightParams>(kBrightParams, "knee"), args->knee,
                     "the preset's");
    cmd->add_flag("--expand-highlights{4}", text->expandHighlights,
                  "8/16-bit input: an inverse tone curve on the near-clipped pixels of the "
                  "lights that --light auto finds (clipped ones become GAIN x white, 4 by "
                  "default; --expand-highlights=8 sets it) so the lights of an 8-bit photo "
                  "flare and its bright sky, snow and walls do not");
    cmd->add_flag("-v,--verbose", args->verbose,
                  "print each pass's time (summed over --repeat runs)");
    addParamOptions<PostFxJobOptions>(cmd, kPostFxJobParams, *args);
    addPartOption(cmd, args->part);
    addLayersInOutputOption(cmd, args->layersInOutput);
    addShotOptions(cmd, args->shot);
    addColorOptions(cmd, text->color);
    cmd->callback([args, text, &exitCode] { exitCode = runPostFx(*text, *args); });
}

}  // namespace flarekit::cli
