// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/PostFxJob.h"
#include "flarekit/job/PixelJob.h"
#include "job/PixelLoad.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/SafeWrite.h"
#include "flarekit/Flare.h"
#include "flarekit/ParamText.h"
#include "job/LayerFiles.h"

namespace flarekit {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class CpuBackend final : public PostFxBackend {
  public:
    std::string name() const override { return "cpu"; }
    bool usesGl() const override { return false; }
    //! `overwrite` and one run: the chain composites over the image and moves it into the
    //! result: no second full-size buffer (a 1080p float frame is 33 MB of fresh pages).
    Result<PostFxResult> run(Image& image, bool overwrite, const PostFxParams& params,
                             const PostFxOptions& options, int repeat, double& warmSeconds,
                             const std::string&, const JobEvents&) const override {
        PostFxResult result;
        warmSeconds = 0;
        if (overwrite && repeat == 1) {
            if (Status s = CpuPostFx().runInPlace(image, params, result, options); !s)
                return s.error();
            result.final = std::move(image);
            return result;
        }
        CpuPostFx chain;
        for (int i = 0; i < repeat; ++i) {
            const auto start = std::chrono::steady_clock::now();
            if (Status s = chain.run(image, params, result, options); !s) return s.error();
            if (i > 0) warmSeconds += secondsSince(start);
        }
        if (repeat > 1) warmSeconds /= repeat - 1;
        return result;
    }
};

//! A layer of the chain at the output's size (the chain runs them at lower resolutions).
struct SizedLayer {
    const char* name;
    Image image;
};
std::vector<SizedLayer> fullSizeLayers(const PostFxResult& r) {
    const int w = r.final.width(), h = r.final.height();
    std::vector<SizedLayer> layers;
    const Image* images[] = {&r.bloom, &r.ghosts, &r.halo, &r.streaks, &r.lens};
    for (std::size_t i = 0; i < std::size(images); ++i)
        layers.push_back({kPostFxLayerNames[i], resizeBilinear(*images[i], w, h)});
    return layers;
}

//! A layer's file: DIR/NAME.exr (a sequence's frame: DIR/FRAME/NAME.exr).
std::string postFxLayerPath(const std::string& dir, const std::string& name) {
    return (std::filesystem::path(dir) / (name + ".exr")).string();
}
std::string frameLayersDir(const std::string& dir, int frame) {
    return dir.empty() ? "" : (std::filesystem::path(dir) / std::to_string(frame)).string();
}

//! What the job reads and writes, for checkJobFiles: the preset, then per image or frame the
//! plate, the output and each layer with the final image.
Status checkPostFxFiles(const PostFxJobOptions& a, const ShotPlan* plan) {
    std::vector<JobFile> reads{{a.preset, "--preset"}}, writes;
    auto image = [&](const std::string& in, const std::string& out, const std::string& dir) {
        reads.push_back({in, "the input"});
        writes.push_back({out, "the output"});
        if (dir.empty()) return;
        for (const char* name : kPostFxLayerNames)
            writes.push_back(
                {postFxLayerPath(dir, name), std::string("layer ") + name + " of --save-layers"});
        writes.push_back({postFxLayerPath(dir, "final"), "layer final of --save-layers"});
    };
    if (!plan) {
        image(a.input, a.output, a.layersDir);
    } else {
        for (int f : plan->frames)
            image(plan->in.path(f), plan->out.path(f), frameLayersDir(a.layersDir, f));
    }
    return checkJobFiles(reads, writes);
}

//! The layers and the final image as EXRs in `dir`, in the input's pixel type: float for a
//! float input (a half would clip what it holds past 65504), half otherwise.
Status writeLayers(const std::string& dir, const std::vector<SizedLayer>& layers,
                   const Image& final, const EncodeSettings& encode, bool floatInput) {
    WriteOptions options;
    options.encode = encode;
    options.format = floatInput ? SampleFormat::Float : SampleFormat::Half;
    std::vector<job_detail::LayerFile> files;
    for (const SizedLayer& layer : layers)
        files.push_back({postFxLayerPath(dir, layer.name), &layer.image});
    files.push_back({postFxLayerPath(dir, "final"), &final});
    return job_detail::writeLayerFiles(dir, files, options);
}

//! The chain's peak per input pixel. Measured at 12 MP: the CPU chain ~43 bytes per pixel over
//! ~135 MiB of process; the GL chain ~83 bytes per pixel (host copies for upload and read-back
//! beside the driver's own) over ~250 MiB with Mesa. Kept layers add their RGBA floats.
JobMemory postFxMemory(const PostFxJobOptions& a) {
    const bool gl = a.backend->usesGl();
    double perPixel = gl ? 96 : 48;
    if (!a.layersDir.empty() || a.layersInOutput)
        perPixel += 6 * 16;  // bloom, ghosts, halo, streaks, lens, final
    // The five layers' channels copied for the output and its larger encode (measured at 4K:
    // 49 bytes per pixel more than --save-layers; 60 counted).
    if (a.layersInOutput) perPixel += 60;
    if (a.expandHighlights) perPixel += 16;
    return {perPixel, (gl ? 256.0 : 160.0) * (1 << 20),
            std::string("postfx ") + (gl ? "gl" : "cpu") + ": " + std::to_string(int(perPixel)) +
                " bytes per pixel"};
}

//! The preset with the job's overrides.
Result<PostFxParams> jobParams(const PostFxJobOptions& a) {
    if (a.presetParams) {
        if (Status s = validatePostFxParams(*a.presetParams); !s)
            return invalidInput(a.preset + ": " + s.error().message);
    }
    auto params =
        a.presetParams ? Result<PostFxParams>(*a.presetParams) : loadPostFxPreset(a.preset);
    if (!params) return params;
    if (a.tonemap) params->tone.op = *a.tonemap;
    if (a.exposure) params->tone.exposure = *a.exposure;
    if (a.threshold) params->bright.threshold = *a.threshold;
    if (a.knee) params->bright.knee = *a.knee;
    return params;
}

//! Verbose: each pass's wall time (with glFinish around each GL pass: llvmpipe's timer queries
//! are not usable) and, on GL, its GPU time.
void sayPassTimes(const std::vector<PassTime>& times, bool gl, const JobEvents& events) {
    char line[160];
    std::snprintf(line, sizeof line, "%-10s %9s %9s %9s", "pass", "wall ms", "MP/s",
                  gl ? "GPU ms" : "");
    events.say(line);
    for (const PassTime& t : times) {
        int n = std::snprintf(line, sizeof line, "%-10s %9.2f %9.1f", t.pass.c_str(),
                              t.wallMilliseconds, t.megapixels / (t.wallMilliseconds * 1e-3));
        if (gl) std::snprintf(line + n, sizeof line - std::size_t(n), " %9.3f", t.milliseconds);
        events.say(line);
    }
}

//! One image (a sequence's frame): `in` through the chain to the image for `out`; the layers
//! into `layersDir` when it is not empty.
//! An image already read (from `in`, for `out`; both only name it) through the chain; the
//! layers into `layersDir` when it is not empty, and into `keptLayers` when it is given.
Result<ImageOutput> chainLoaded(const PostFxJobOptions& a, LoadedImage& loaded,
                                const std::string& in, const std::string& out,
                                const std::string& layersDir, const JobEvents& events,
                                std::vector<SizedLayer>* keptLayers) {
    auto params = jobParams(a);
    if (!params) return params.error();
    // No curve named, and the preset has none: the default display curve, as apply's.
    if (!a.tonemap && params->tone.op == ToneOperator::None)
        params->tone.op = defaultDisplayCurve(loaded.wasFloat, out);
    std::vector<PassTime> times;
    PostFxOptions options;
    options.keepLayers = !layersDir.empty() || a.layersInOutput || keptLayers;
    options.times = a.verbose ? &times : nullptr;
    // Expanded highlights: the chain sees the expanded image, the output keeps the original
    // pixels (the expansion is taken back off the additive composite).
    const bool expand = a.expandHighlights && !loaded.wasFloat;
    // The GL chain moves halves where they lose nothing: an input read from a half EXR, a
    // result only kept as a half EXR (the layers and expanded highlights use the floats).
    options.halfInput = loaded.halfExact;
    options.halfReadback =
        outputSampleFormat(out) == SampleFormat::Half && !options.keepLayers && !expand;
    if (a.expandHighlights && loaded.wasFloat)
        events.warn(in + ": --expand-highlights is for 8/16-bit input; HDR input is used as it is");
    Image expanded;
    if (expand) {
        expanded = loaded.image;
        // Only around the frame's lights: a bright sky or snow expanded would flare as a slab.
        const LightSearch lights = expandHighlightsAtLights(expanded, *a.expandHighlights);
        if (lights.lights.empty())
            events.warn(in + ": --expand-highlights: no light to expand (" + lights.whyNone + ")");
        params->bright.knownWhite = 1.f;  // still display-referred: its white is the display's
    }
    // The image as read is needed afterwards only to take an expansion back off.
    Image& chainInput = expand ? expanded : loaded.image;
    double warmSeconds = 0;
    auto result =
        a.backend->run(chainInput, !expand, *params, options, a.repeat, warmSeconds, in, events);
    if (!result) return result.error();
    if (a.repeat > 1) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "flarekit-postfx %dx%d %s %s: %.4f s per run (mean of %d after the first)",
                      result->final.width(), result->final.height(), a.backend->name().c_str(),
                      params->name.c_str(), warmSeconds, a.repeat - 1);
        events.say(line);
    }
    if (expand && params->tone.op == ToneOperator::None) {
        float* f = result->final.data();
        const float *e = expanded.data(), *o = loaded.image.data();
        for (std::size_t i = 0; i < result->final.pixelCount() * 4; ++i)
            if (i % 4 != 3) f[i] = std::max(0.f, f[i] - (e[i] - o[i]));
    }
    if (a.verbose) sayPassTimes(times, a.backend->usesGl(), events);
    // Resized once for the layer files and the output's channels alike.
    std::vector<SizedLayer> layers =
        options.keepLayers ? fullSizeLayers(*result) : std::vector<SizedLayer>{};
    if (!layersDir.empty()) {
        const bool floatInput = loaded.wasFloat && !loaded.halfExact;
        if (Status s = writeLayers(layersDir, layers, result->final, a.encode, floatInput); !s)
            return s.error();
    }
    ImageOutput output{std::move(result->final), {}};
    output.options.alpha = loaded.hasAlpha;
    output.options.encode = a.encode;
    output.options.exrExtras = keptExtras(loaded, in, out, events);
    if (a.layersInOutput) {
        std::vector<NamedLayer> named;
        for (const SizedLayer& layer : layers) named.push_back({layer.name, &layer.image});
        output.options.exrExtras = withLayerChannels(output.options.exrExtras, named);
    }
    if (a.color) a.color->toOutput(output.image, output.options);
    if (keptLayers) *keptLayers = std::move(layers);
    return output;
}

Result<ImageOutput> runChain(const PostFxJobOptions& a, const std::string& in,
                             const std::string& out, const std::string& layersDir,
                             const JobEvents& events) {
    if (Status s = checkLayersFit(a.layersInOutput, out); !s) return s.error();
    auto loaded = readJobInput(in, postFxMemory(a), events, {a.part});
    if (!loaded) return loaded.error();
    if (Status s = checkPartsFit(*loaded, in, out); !s) return s.error();
    if (a.color) a.color->toWorking(*loaded);
    return chainLoaded(a, *loaded, in, out, layersDir, events, nullptr);
}

}  // namespace

std::shared_ptr<const PostFxBackend> cpuPostFxBackend() {
    static const auto backend = std::make_shared<const CpuBackend>();
    return backend;
}

Status checkExpandHighlights(double gain, const std::string& text) {
    const Param<ExpandHighlights>& p = kExpandHighlightsParams[0];
    if (std::isfinite(gain) && numberFits(p, gain)) return Ok{};
    return invalidInput("--expand-highlights: expected a gain in " +
                        formatParamRange(p.min, p.max) + ", got '" + text + "'");
}

Result<JobReport> runPostFxJob(const PostFxJobOptions& a, const JobEvents& events) {
    if (a.expandHighlights) {
        const double gain = *a.expandHighlights;
        if (Status s = checkExpandHighlights(gain, formatParamNumber(gain)); !s) return s.error();
    }
    JobReport report;
    report.sequence = isFramePattern(a.input);
    if (!report.sequence) {
        if (Status s = checkSingleImage(a.input, a.shot); !s) return s.error();
        if (Status s = checkPostFxFiles(a, nullptr); !s) return s.error();
        if (Status s = writeImageJob(
                a.output, [&] { return runChain(a, a.input, a.output, a.layersDir, events); });
            !s)
            return s.error();
        return report;
    }
    if (a.repeat > 1) return invalidInput("--repeat: for one image, not a sequence");
    auto plan = planShot(a.input, a.output, a.shot, {}, events);
    if (!plan) return plan.error();
    if (Status s = checkPostFxFiles(a, &*plan); !s) return s.error();
    auto parallel = framesInFlight(*plan, postFxMemory(a), a.backend->usesGl());
    if (!parallel) return parallel.error();
    auto summary = runShot(
        *plan, *parallel,
        [&](const ShotFrame& f) {
            // A sequence's layers go into a folder per frame: DIR/1001/bloom.exr, ...
            return runChain(a, f.in, f.out, frameLayersDir(a.layersDir, f.frame), events);
        },
        events);
    if (!summary) return summary.error();
    report.shot = *summary;
    return report;
}

Result<PixelOutput> postFxPixels(const PostFxJobOptions& options, PixelInput input,
                                 const JobEvents& events, bool keepLayers) {
    PostFxJobOptions a = options;
    a.layersDir.clear(), a.layersInOutput = false, a.color = nullptr;
    if (a.expandHighlights) {
        const double gain = *a.expandHighlights;
        if (Status s = checkExpandHighlights(gain, formatParamNumber(gain)); !s) return s.error();
    }
    const std::string name = input.name;
    auto loaded = job_detail::loadedFromPixels(std::move(input), postFxMemory(a), events);
    if (!loaded) return loaded.error();
    std::vector<SizedLayer> layers;
    auto out = chainLoaded(a, *loaded, name, "", "", events, keepLayers ? &layers : nullptr);
    if (!out) return out.error();
    PixelOutput result{std::move(out->image), {}};
    for (SizedLayer& layer : layers) result.layers.push_back({layer.name, std::move(layer.image)});
    return result;
}

}  // namespace flarekit
