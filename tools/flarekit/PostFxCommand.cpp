// SPDX-License-Identifier: Apache-2.0
// flarekit postfx: the image-based lens flare (Killzone 2 / Kawase ghosts, bloom, halo,
// streaks, chromatic aberration, starburst, dirt) on any image, CPU or OpenGL.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "ColorManagement.h"
#include "Common.h"
#include "ParamOptions.h"
#include "ShotRun.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFx.h"
#include "flarekit/Tonemap.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/HeadlessGl.h"
#endif

namespace flarekit::cli {

namespace {
struct PostFxArgs {
    std::string in, out, preset = kDefaultPostFxPreset, backend = "cpu", layersDir,
                         tonemap = "preset", glTransfer = "auto";
    std::optional<float> exposure, threshold, knee;
    //! --expand-highlights[=GAIN], as given ("" off): a flag with an optional value, which
    //! CLI11 would round to an integer if it were bound to a number.
    std::string expandHighlights;
    int repeat = 1;
    bool verbose = false;
    ShotArgs shot;
    ColorArgs color;
    std::shared_ptr<const ColorManagement> colors;  //!< built from `color` before the run
};
inline constexpr Param<PostFxArgs> kPostFxArgParams[] = {
    param<&PostFxArgs::repeat>(
        "repeat", 1, 1000, "runs",
        "run the chain N times and print the mean time of the warm runs (benchmarking)"),
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//! Runs the chain `repeat` times (buffers kept, as in a video) and, when repeating, prints the
//! mean time of the runs after the first: the figure bench/peers/run_blender_peer.sh compares.
//! `overwrite`: the caller has no further use for `image`, so one CPU run composites over it
//! (and moves it into the result): no second full-size buffer (a 1080p float frame is 33 MB of
//! fresh pages).
Result<PostFxResult> runBackend(const PostFxArgs& a, [[maybe_unused]] const std::string& in,
                                Image& image, bool overwrite, const PostFxParams& params,
                                const PostFxOptions& options) {
    PostFxResult result;
    double warmSeconds = 0;
    if (a.backend == "cpu" && overwrite && a.repeat == 1) {
        if (Status s = CpuPostFx().runInPlace(image, params, result, options); !s) return s.error();
        result.final = std::move(image);
    } else if (a.backend == "cpu") {
        CpuPostFx chain;
        for (int i = 0; i < a.repeat; ++i) {
            const auto start = std::chrono::steady_clock::now();
            if (Status s = chain.run(image, params, result, options); !s) return s.error();
            if (i > 0 || a.repeat == 1) warmSeconds += secondsSince(start);
        }
    } else {
#if FLAREKIT_HAS_GL
        auto context = createHeadlessGl();
        if (!context) return context.error();
        if (Status s = checkGlFrame(image.width(), image.height(), 1, in + ": image"); !s)
            return s.error();
        auto chain = GpuPostFx::create();
        if (!chain) return chain.error();
        if (a.verbose) std::printf("OpenGL: %s\n", (*context)->renderer().c_str());
        // Halves halve the bytes a GPU moves over its bus. On llvmpipe the "GPU" is this CPU,
        // where they only add a conversion each way (a 4K read-back: 121 ms as floats, 162 ms
        // as halves), so `auto` keeps floats there.
        const bool software = (*context)->renderer().find("llvmpipe") != std::string::npos ||
                              (*context)->renderer().find("softpipe") != std::string::npos;
        PostFxOptions glOptions = options;
        if (a.glTransfer == "float" || (a.glTransfer == "auto" && software))
            glOptions.halfInput = glOptions.halfReadback = false;
        for (int i = 0; i < a.repeat; ++i) {
            const auto start = std::chrono::steady_clock::now();
            auto r = chain->run(image, params, glOptions);  // upload, passes, read-back
            if (!r) return r.error();
            result = std::move(*r);
            if (i > 0 || a.repeat == 1) warmSeconds += secondsSince(start);
        }
#else
        return builtWithoutGl("postfx --backend gl");
#endif
    }
    if (a.repeat > 1) {
        std::printf("flarekit-postfx %dx%d %s %s: %.4f s per run (mean of %d after the first)\n",
                    image.width(), image.height(), a.backend.c_str(), params.name.c_str(),
                    warmSeconds / (a.repeat - 1), a.repeat - 1);
    }
    return result;
}

Status writeLayers(const std::string& dir, const PostFxResult& r) {
    if (Status s = makeOutputDirectory(dir); !s) return s;
    const int w = r.final.width(), h = r.final.height();
    for (auto [name, layer] :
         {std::pair{"bloom", &r.bloom}, std::pair{"ghosts", &r.ghosts}, std::pair{"halo", &r.halo},
          std::pair{"streaks", &r.streaks}, std::pair{"lens", &r.lens}}) {
        const std::string path =
            (std::filesystem::path(dir) / (std::string(name) + ".exr")).string();
        if (Status s = writeImage(path, resizeBilinear(*layer, w, h)); !s) return s;
    }
    return writeImage((std::filesystem::path(dir) / "final.exr").string(), r.final);
}

//! The chain's peak per input pixel. Measured at 12 MP: the CPU chain ~43 bytes per pixel over
//! ~135 MiB of process; the GL chain ~83 bytes per pixel (host copies for upload and read-back
//! beside the driver's own) over ~250 MiB with Mesa. Kept layers add their RGBA floats.
JobMemory postFxMemory(const PostFxArgs& a) {
    const bool gl = a.backend == "gl";
    double perPixel = gl ? 96 : 48;
    if (!a.layersDir.empty()) perPixel += 6 * 16;  // bloom, ghosts, halo, streaks, lens, final
    if (!a.expandHighlights.empty()) perPixel += 16;
    return {perPixel, (gl ? 256.0 : 160.0) * (1 << 20),
            std::string("postfx ") + (gl ? "gl" : "cpu") + ": " + std::to_string(int(perPixel)) +
                " bytes per pixel"};
}

//! One image (a sequence's frame): `in` through the chain to the image for `out`; the layers
//! into `layersDir` when it is not empty.
Result<ImageOutput> runChain(const PostFxArgs& a, const std::string& in, const std::string& out,
                             const std::string& layersDir) {
    auto params = loadPostFxPreset(a.preset);
    if (!params) return params.error();
    if (const auto op = namedToneOperator(a.tonemap)) params->tone.op = *op;
    if (a.exposure) params->tone.exposure = *a.exposure;
    if (a.threshold) params->bright.threshold = *a.threshold;
    if (a.knee) params->bright.knee = *a.knee;
    auto loaded = readInputImage(in, postFxMemory(a));
    if (!loaded) return loaded.error();
    if (a.colors) a.colors->toWorking(*loaded);
    // --tonemap preset, and the preset has no curve: the default display curve, as `apply`'s.
    if (a.tonemap == "preset" && params->tone.op == ToneOperator::None)
        params->tone.op = defaultDisplayCurve(loaded->wasFloat, out);

    std::vector<PassTime> times;
    PostFxOptions options;
    options.keepLayers = !layersDir.empty();
    options.times = a.verbose ? &times : nullptr;
    // --expand-highlights: the chain sees the expanded image, the output keeps the original
    // pixels (the expansion is taken back off the additive composite).
    float gain = 0.f;
    if (!a.expandHighlights.empty()) {
        char* end = nullptr;
        const double g = std::strtod(a.expandHighlights.c_str(), &end);
        if (end == a.expandHighlights.c_str() || *end != '\0' || !(g >= 1.0 && g <= 1e4))
            return invalidInput("--expand-highlights: expected a gain in [1, 10000], got '" +
                                a.expandHighlights + "'");
        gain = float(g);
    }
    const bool expand = gain > 0.f && !loaded->wasFloat;
    // The GL chain moves halves where they lose nothing: an input read from a half EXR, a
    // result only kept as a half EXR (the layers and --expand-highlights use the floats).
    options.halfInput = loaded->halfExact;
    options.halfReadback =
        outputSampleFormat(out) == SampleFormat::Half && layersDir.empty() && !expand;
    if (gain > 0.f && loaded->wasFloat)
        warn(in + ": --expand-highlights is for 8/16-bit input; HDR input is used as it is");
    Image expanded;
    if (expand) {
        expanded = loaded->image;
        expandHighlights(expanded, gain);
        params->bright.knownWhite = 1.f;  // still display-referred: its white is the display's
    }
    // The image as read is needed afterwards only to take an expansion back off.
    auto result = runBackend(a, in, expand ? expanded : loaded->image, !expand, *params, options);
    if (!result) return result.error();
    if (expand && params->tone.op == ToneOperator::None) {
        float* f = result->final.data();
        const float *e = expanded.data(), *o = loaded->image.data();
        for (std::size_t i = 0; i < result->final.pixelCount() * 4; ++i)
            if (i % 4 != 3) f[i] = std::max(0.f, f[i] - (e[i] - o[i]));
    }
    if (a.verbose) {
        // Wall time (with glFinish around each GL pass): llvmpipe's timer queries are not usable.
        std::printf("%-10s %9s %9s %9s\n", "pass", "wall ms", "MP/s",
                    a.backend == "gl" ? "GPU ms" : "");
        for (const PassTime& t : times) {
            std::printf("%-10s %9.2f %9.1f", t.pass.c_str(), t.wallMilliseconds,
                        t.megapixels / (t.wallMilliseconds * 1e-3));
            if (a.backend == "gl") std::printf(" %9.3f", t.milliseconds);
            std::printf("\n");
        }
    }
    if (!layersDir.empty()) {
        if (Status s = writeLayers(layersDir, *result); !s) return s.error();
    }
    ImageOutput output{std::move(result->final), {}};
    output.options.alpha = loaded->hasAlpha;
    output.options.exrExtras = keptExtras(*loaded, in, out);
    if (a.colors) a.colors->toOutput(output.image, output.options);
    return output;
}

int runPostFx(const PostFxArgs& args) {
    PostFxArgs a = args;
    auto colors = ColorManagement::create(a.color);
    if (!colors) return report(colors.error());
    a.colors = *colors;
    if (!isFramePattern(a.in)) {
        if (Status s = checkSingleImage(a.in, a.shot); !s) return report(s.error());
        return runImageJob(a.out, [&] { return runChain(a, a.in, a.out, a.layersDir); });
    }
    if (a.repeat > 1) return report(invalidInput("--repeat: for one image, not a sequence"));
    auto plan = planShot(a.in, a.out, a.shot);
    if (!plan) return report(plan.error());
    auto parallel = framesInFlight(*plan, postFxMemory(a), a.backend == "gl");
    if (!parallel) return report(parallel.error());
    return runShot(*plan, "postfx", *parallel, [&](const ShotFrame& f) {
        // A sequence's layers go into a folder per frame: DIR/1001/bloom.exr, ...
        const std::string layers =
            a.layersDir.empty()
                ? ""
                : (std::filesystem::path(a.layersDir) / std::to_string(f.frame)).string();
        return runChain(a, f.in, f.out, layers);
    });
}
}  // namespace

void addPostFxCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<PostFxArgs>();
    CLI::App* cmd = app.add_subcommand("postfx",
                                       "Image-based lens flare (Killzone 2 / Kawase ghosts, bloom, "
                                       "halo, streaks, dirt) on any image");
    cmd->add_option("input", args->in,
                    "input image (EXR kept linear; 8-bit files are sRGB-decoded; grey and "
                    "grey+alpha promoted), or a frame pattern (shot.####.exr) for a sequence")
        ->required();
    cmd->add_option("-o,--output", args->out,
                    "output image; format and bit depth follow the extension")
        ->required();
    cmd->add_option(
           "--preset", args->preset,
           "shipped post-process preset (killzone2, modern, anamorphic, subtle) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--backend", args->backend, "cpu, or gl (OpenGL 4.5 through headless EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    cmd->add_option("--gl-transfer", args->glTransfer,
                    "--backend gl: how the image moves to and from the GPU: half (half floats "
                    "where nothing is lost: a half EXR in, a half EXR out), float, or auto (half "
                    "on a GPU, float on llvmpipe, where halves cost a conversion and save nothing)")
        ->check(CLI::IsMember({"auto", "half", "float"}))
        ->capture_default_str();
    cmd->add_option(
        "--save-layers", args->layersDir,
        "also write bloom, ghosts, halo, streaks, lens and final (linear EXR) into DIR (for a "
        "sequence, into DIR/FRAME/)");
    cmd->add_option("--tonemap", args->tonemap,
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
    cmd->add_flag("--expand-highlights{4}", args->expandHighlights,
                  "8/16-bit input: an inverse tone curve on near-clipped pixels (clipped ones "
                  "become GAIN x white, 4 by default; --expand-highlights=8 sets it) so the "
                  "lights of an 8-bit photo flare");
    cmd->add_flag("-v,--verbose", args->verbose,
                  "print each pass's time (summed over --repeat runs)");
    addParamOptions<PostFxArgs>(cmd, kPostFxArgParams, *args);
    addShotOptions(cmd, args->shot);
    addColorOptions(cmd, args->color);
    cmd->callback([args, &exitCode] { exitCode = runPostFx(*args); });
}

}  // namespace flarekit::cli
