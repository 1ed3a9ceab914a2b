// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PixelJob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/SafeWrite.h"
#include "job/LayerFiles.h"
#include "job/PixelLoad.h"

namespace flarekit {

namespace {

class CpuBackend final : public LensBackend {
  public:
    std::string name() const override { return "cpu"; }
    bool usesGl() const override { return false; }
    Result<LensFlareLayers> render(const Lens& lens, int width, int height,
                                   const std::vector<LensLight>& lights,
                                   const LensRenderOptions& options, const std::string&, bool,
                                   const JobEvents&) const override {
        return renderLensFlare(lens, width, height, lights, options);
    }
};

//! The render's peak per pixel: the input, the three layers, their sum and the composite; with
//! --layers-in-output the four layers' channels copied for the output and its larger encode
//! (measured at 4K: 49 bytes per pixel more than without; 64 counted).
JobMemory lensRenderMemory(const LensJobOptions& a) {
    const double perPixel = 6 * 16.0 + (a.layersInOutput ? 64 : 0);
    return {
        perPixel, 256.0 * (1 << 20),
        "lens render: " + std::to_string(int(perPixel)) + " bytes per pixel and the traced meshes"};
}

std::vector<LensLight> lensLights(const LensJobOptions& a, const std::string& in,
                                  const Image& image, const JobEvents& events) {
    const int diagonal = int(std::hypot(double(image.width()), double(image.height())));
    if (a.lightMode == LensLightMode::All)
        return brightSources(image, a.threshold, std::max(1, diagonal / 64), a.maxSources);
    if (a.lightMode == LensLightMode::Brightest) {
        // The brightest region: bright pixels merged over cells a sixteenth of the diagonal.
        auto lights = brightSources(image, a.threshold, std::max(1, diagonal / 16), 1);
        if (lights.empty())
            events.warn(in + ": no pixel at or above --threshold " + std::to_string(a.threshold) +
                        ": no light, no flare");
        return lights;
    }
    // Its energy: the bright pixels within a 32nd of the diagonal.
    LensLight l = sourceAt(image, a.light.x, a.light.y, diagonal / 32.0, a.threshold);
    if (l.energy[0] + l.energy[1] + l.energy[2] <= 0) {
        char at[64];
        std::snprintf(at, sizeof at, "%g,%g", double(a.light.x), double(a.light.y));
        events.warn(in + ": nothing at or above --threshold near " + at +
                    ": the light is given the energy of a 100-pixel source of 100 x white");
        l.energy = {1e4, 1e4, 1e4};
    }
    return {l};
}

//! The flare layers through the chosen backend; many sources report a step per source drawn
//! and stop when the job is cancelled.
Result<LensFlareLayers> renderLayers(const LensJobOptions& a, const std::string& in,
                                     const Lens& lens, const Image& image,
                                     const std::vector<LensLight>& lights,
                                     const JobEvents& events) {
    LensRenderOptions render = a.render;
    if (lights.size() > 1)
        render.progress = [&](int done, int total) {
            if (events.steps) events.steps(in, "source", done, total);
            return !events.stopRequested();
        };
    return a.backend->render(lens, image.width(), image.height(), lights, render, in, a.verbose,
                             events);
}

//! The layers' names: the render's three parts and their sum.
constexpr const char* kLensLayerNames[] = {"ghosts", "starburst", "glare", "flare"};

//! The layers' images by kLensLayerNames, for their files and the output's channels alike.
std::vector<NamedLayer> namedLensLayers(const LensFlareLayers& layers, const Image& flare) {
    const Image* images[] = {&layers.ghosts, &layers.starburst, &layers.glare, &flare};
    std::vector<NamedLayer> named;
    for (std::size_t i = 0; i < std::size(images); ++i)
        named.push_back({kLensLayerNames[i], images[i]});
    return named;
}

//! A layer's file: DIR/NAME + `suffix` + .exr (".1001" for a sequence's frame).
std::string lensLayerPath(const std::string& dir, const std::string& name,
                          const std::string& suffix) {
    return (std::filesystem::path(dir) / (name + suffix + ".exr")).string();
}

Status writeLensLayers(const std::string& dir, const std::string& suffix,
                       const LensFlareLayers& layers, const Image& flare,
                       const EncodeSettings& encode) {
    WriteOptions options;
    options.encode = encode;
    std::vector<job_detail::LayerFile> files;
    for (const auto& [name, image] : namedLensLayers(layers, flare))
        files.push_back({lensLayerPath(dir, name, suffix), image});
    return job_detail::writeLayerFiles(dir, files, options);
}

//! What the job reads and writes, for checkJobFiles: the lens, then per image or frame the
//! plate, the output and each layer.
Status checkLensFiles(const LensJobOptions& a, const ShotPlan* plan) {
    std::vector<JobFile> reads{{a.lens, "the lens"}, {a.dirtFile, "--dirt-file"}}, writes;
    auto image = [&](const std::string& in, const std::string& out, const std::string& suffix) {
        reads.push_back({in, "the input"});
        writes.push_back({out, "the output"});
        if (a.layersDir.empty()) return;
        for (const char* name : kLensLayerNames)
            writes.push_back({lensLayerPath(a.layersDir, name, suffix),
                              std::string("layer ") + name + " of --layers"});
    };
    if (!plan) {
        image(a.input, a.output, "");
    } else {
        for (int f : plan->frames)
            image(plan->in.path(f), plan->out.path(f),
                  frameSuffix(*plan, {f, plan->in.path(f), plan->out.path(f)}));
    }
    return checkJobFiles(reads, writes);
}

//! An image already read (from `in`, for `out`; both only name it) with its lens flare; the
//! layers as DIR/NAME + `layerSuffix` + .exr and into `keptLayers` when it is given.
Result<ImageOutput> lensLoaded(const LensJobOptions& a, const Lens& lens, LoadedImage& loaded,
                               const std::string& in, const std::string& out,
                               const JobEvents& events, const std::string& layerSuffix,
                               std::vector<std::pair<std::string, Image>>* keptLayers) {
    Image& image = loaded.image;
    // 8/16-bit photographs clip their lights at 1: expand them back (postfx's inverse curve) so
    // a clipped sun carries the energy a flare needs; the output keeps the original pixels.
    const bool expand = !loaded.wasFloat && a.expandGain > 1.0;
    Image expanded;
    if (expand) {
        expanded = image;
        expandHighlights(expanded, float(a.expandGain));
    }
    const auto lights = lensLights(a, in, expand ? expanded : image, events);
    auto layers = renderLayers(a, in, lens, image, lights, events);
    if (!layers) return layers.error();
    const Image flare = lensFlareSum(*layers);
    if (!a.layersDir.empty()) {
        if (Status s = writeLensLayers(a.layersDir, layerSuffix, *layers, flare, a.encode); !s)
            return s.error();
    }
    Image composite = image;
    for (std::size_t i = 0; i < composite.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) composite.data()[4 * i + c] += flare.data()[4 * i + c];
    }
    toneMapImage(composite, a.tonemap.value_or(defaultDisplayCurve(loaded.wasFloat, out)), 1.f);
    ImageOutput result{std::move(composite), {}};
    result.options.alpha = loaded.hasAlpha;
    // An EXR plate's other channels, attributes and parts go on to an EXR output.
    result.options.exrExtras = keptExtras(loaded, in, out, events);
    if (a.layersInOutput)
        result.options.exrExtras =
            withLayerChannels(result.options.exrExtras, namedLensLayers(*layers, flare));
    result.options.encode = a.encode;
    if (keptLayers)
        for (const auto& [name, layer] : namedLensLayers(*layers, flare))
            keptLayers->push_back({name, *layer});
    char line[400];
    std::snprintf(line, sizeof line, "%s: %zu light(s), flare through %s (f = %.1f mm)",
                  (out.empty() ? in : out).c_str(), lights.size(), lens.name.c_str(),
                  paraxial(lens).focalLength);
    events.say(line);
    return result;
}

//! --dirt-file read into the render's pupil mask, once for every frame of a sequence.
Status readDirtMask(LensJobOptions& a) {
    if (a.dirtFile.empty()) return Ok{};
    auto mask = readImage(a.dirtFile, {16.0, 0.0, "--dirt-file: 16 bytes per pixel"});
    if (!mask) return mask.error();
    a.render.pupilMask = std::make_shared<const Image>(std::move(mask->image));
    return Ok{};
}

//! One image (a sequence's frame) `in` for `out`; the layers as DIR/NAME + `layerSuffix` + .exr.
Result<ImageOutput> renderOne(const LensJobOptions& a, const std::string& in,
                              const std::string& out, const JobEvents& events,
                              const std::string& layerSuffix = "") {
    if (Status s = checkLayersFit(a.layersInOutput, out); !s) return s.error();
    auto lens = openJobLens(a);
    if (!lens) return lens.error();
    auto loaded = readJobInput(in, lensRenderMemory(a), events, {a.part});
    if (!loaded) return loaded.error();
    if (Status s = checkPartsFit(*loaded, in, out); !s) return s.error();
    return lensLoaded(a, *lens, *loaded, in, out, events, layerSuffix, nullptr);
}

}  // namespace

Result<Lens> openJobLens(const LensJobOptions& a) {
    auto lens = a.lensData ? Result<Lens>(*a.lensData) : loadLens(a.lens);
    if (!lens) return lens;
    if (a.fNumber > 0) return stopDown(*lens, a.fNumber);
    return lens;
}

std::shared_ptr<const LensBackend> cpuLensBackend() {
    static const auto backend = std::make_shared<const CpuBackend>();
    return backend;
}

Result<JobReport> runLensJob(const LensJobOptions& options, const JobEvents& events) {
    if (options.lightMode == LensLightMode::At) {
        if (Status s = checkLightCoordinates(options.light, "--light"); !s) return s.error();
    }
    LensJobOptions a = options;
    if (Status s = readDirtMask(a); !s) return s.error();
    JobReport report;
    report.sequence = isFramePattern(a.input);
    if (!report.sequence) {
        if (Status s = checkSingleImage(a.input, a.shot); !s) return s.error();
        if (Status s = checkLensFiles(a, nullptr); !s) return s.error();
        if (Status s =
                writeImageJob(a.output, [&] { return renderOne(a, a.input, a.output, events); });
            !s)
            return s.error();
        return report;
    }
    auto plan = planShot(a.input, a.output, a.shot, {}, events);
    if (!plan) return plan.error();
    if (Status s = checkLensFiles(a, &*plan); !s) return s.error();
    auto parallel = framesInFlight(*plan, lensRenderMemory(a), a.backend->usesGl());
    if (!parallel) return parallel.error();
    auto summary = runShot(
        *plan, *parallel,
        [&](const ShotFrame& f) {
            return renderOne(a, f.in, f.out, events, frameSuffix(*plan, f));
        },
        events);
    if (!summary) return summary.error();
    report.shot = *summary;
    return report;
}

Result<PixelOutput> lensPixels(const LensJobOptions& options, PixelInput input,
                               const JobEvents& events, bool keepLayers) {
    LensJobOptions a = options;
    a.layersDir.clear(), a.layersInOutput = false;
    if (a.lightMode == LensLightMode::At) {
        if (Status s = checkLightCoordinates(a.light, "--light"); !s) return s.error();
    }
    if (Status s = readDirtMask(a); !s) return s.error();
    auto lens = openJobLens(a);
    if (!lens) return lens.error();
    const std::string name = input.name;
    auto loaded = job_detail::loadedFromPixels(std::move(input), lensRenderMemory(a), events);
    if (!loaded) return loaded.error();
    PixelOutput result;
    auto out =
        lensLoaded(a, *lens, *loaded, name, "", events, "", keepLayers ? &result.layers : nullptr);
    if (!out) return out.error();
    result.image = std::move(out->image);
    return result;
}

}  // namespace flarekit
