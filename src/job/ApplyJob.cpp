// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/PixelJob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "core/SafeWrite.h"
#include "flarekit/job/ShotTracking.h"
#include "job/LayerFiles.h"
#include "job/PixelLoad.h"
#include "job/ShotLight.h"

namespace flarekit {

namespace {

std::string format(const char* fmt, auto... values) {
    char line[400];
    std::snprintf(line, sizeof line, fmt, values...);
    return line;
}

//! Verbose: every region the light finder considered, most flux first.
void sayCandidates(const LightSearch& search, const JobEvents& events) {
    std::vector<LightCandidate> sorted = search.candidates;
    std::stable_sort(
        sorted.begin(), sorted.end(),
        [](const LightCandidate& a, const LightCandidate& b) { return a.flux > b.flux; });
    events.say(
        format("peak luminance %.4g, median %.4g, %s; %zu candidates (most flux first, at "
               "most 12 listed):",
               double(search.peak), double(search.frameKey),
               search.displayReferred ? "display-referred (clipped pixels x clipped-gain)"
                                      : "scene-referred HDR",
               sorted.size()));
    //! Candidates listed at most by flux: the lights and the closest misses, not every speck of
    //! sky. The lights and the candidate that came closest (a small sun only too faint) are
    //! listed after them wherever they rank.
    constexpr std::size_t kListed = 12;
    if (sorted.size() > kListed) {
        const std::size_t closest = closestCandidate(sorted);  // the one a warning names
        std::vector<LightCandidate> listed(sorted.begin(), sorted.begin() + kListed);
        for (std::size_t i = kListed; i < sorted.size(); ++i)
            if (sorted[i].accepted || i == closest) listed.push_back(sorted[i]);
        sorted = std::move(listed);
    }
    for (const LightCandidate& c : sorted)
        events.say(format(
            "  at %.1f,%.1f radius %.1f px, peak %.4g, flux %.4g, %.2fx "
            "surroundings, compactness %.2f, halo %.2f,%s flare scale %.4f: %s",
            double(c.position.x), double(c.position.y), double(c.radius), double(c.peak), c.flux,
            double(c.prominence), double(c.compactness), double(c.halo),
            search.displayReferred
                ? format(" %.0f%% at white,", 100.0 * double(whiteShare(c))).c_str()
                : format(" aureole %.4g over %d rings,", c.aureoleFlux, c.aureoleRings).c_str(),
            double(c.flareScale), c.verdict.c_str()));
}

//! The lights of one frame, each a position and an intensity.
using Lights = std::vector<std::pair<Point, float>>;
using LightsOf = std::function<Result<Lights>(const LoadedImage&)>;

//! The layer files the preset gives (kFlareLayerNames it has elements of) and the whole flare.
std::vector<std::string> layerNamesOf(const Preset& preset) {
    std::vector<std::string> names;
    for (int layer = 0; layer < int(std::size(kFlareLayerNames)); ++layer)
        for (const ElementParams& e : preset.elements)
            if (flareLayerOf(e.type) == layer) {
                names.push_back(kFlareLayerNames[layer]);
                break;
            }
    names.push_back("flare");
    return names;
}

//! Measured peak (12 MP, both depths): ~135 MiB of process plus ~43 bytes per pixel: the RGBA
//! floats, the orientation copy, the encoded samples and the file bytes (plus the decode buffer,
//! which readImage adds). Layers add per layer file (each pass and the whole flare): its RGBA
//! floats and its encode, measured at 4K with tanczos-classic's 5 files as 92 bytes per pixel
//! for --layers DIR (20 per file) and 160 for --layers-in-output (32 per file: the channels'
//! copy and the output's larger encode on top).
JobMemory applyMemory(const ApplyOptions& a, const Preset& preset) {
    const double files = double(layerNamesOf(preset).size());
    double perPixel = 40;
    if (a.layersInOutput)
        perPixel += 36 * files;
    else if (!a.layersDir.empty() || a.flareOnly)
        perPixel += 20 * files;
    return {perPixel, 160.0 * (1 << 20),
            "apply: " + std::to_string(int(perPixel)) + " bytes per pixel"};
}

//! No light given: the lights the finder keeps in the frame, each scaled by its flare scale.
Lights autoLights(const ApplyOptions& a, const std::string& in, const Image& image,
                  const JobEvents& events) {
    const LightSearch search = findLights(image, a.lightSearch);
    if (a.verbose) sayCandidates(search, events);
    if (search.lights.empty())
        events.warn(in + ": " + search.whyNone +
                    "; image written unchanged (--light X,Y places one)");
    Lights lights;
    for (const LightCandidate& light : search.lights)
        lights.push_back({light.position, a.intensity * light.flareScale});
    return lights;
}

//! Layers: each pass and the whole flare as float EXRs in DIR, named NAME + `suffix` + .exr
//! (".1001" for a sequence's frame, so each pass is a sequence of its own).
std::string flareLayerPath(const std::string& dir, const std::string& name,
                           const std::string& suffix) {
    return (std::filesystem::path(dir) / (name + suffix + ".exr")).string();
}
Status writeFlareLayers(const std::string& dir, const std::string& suffix,
                        const std::vector<FlareLayer>& layers, const Image& flare,
                        const EncodeSettings& encode) {
    WriteOptions linear;
    linear.format = SampleFormat::Float;
    linear.encode = encode;
    std::vector<job_detail::LayerFile> files;
    for (const FlareLayer& layer : layers)
        files.push_back({flareLayerPath(dir, layer.name, suffix), &layer.image});
    files.push_back({flareLayerPath(dir, "flare", suffix), &flare});
    return job_detail::writeLayerFiles(dir, files, linear);
}

//! What the job reads and writes, for checkJobFiles: the preset, track and camera, then per
//! image or frame the plate, its matte, the output and each layer the preset draws.
Status checkApplyFiles(const ApplyOptions& a, const Preset& preset, const ShotPlan* plan,
                       const std::optional<FramePattern>& matte) {
    const std::vector<std::string> layerNames = layerNamesOf(preset);
    std::vector<JobFile> reads{
        {a.preset, "--preset"}, {a.lightTrack, "--light-track"}, {a.camera, "--camera"}};
    std::vector<JobFile> writes;
    if (!a.writeTrack.empty()) writes.push_back({a.writeTrack, "--write-track"});
    auto image = [&](const std::string& in, const std::string& matteFile, const std::string& out,
                     const std::string& suffix) {
        reads.push_back({in, "the input"});
        if (!matteFile.empty()) reads.push_back({matteFile, "--matte"});
        writes.push_back({out, "the output"});
        if (!a.layersDir.empty())
            for (const std::string& name : layerNames)
                writes.push_back(
                    {flareLayerPath(a.layersDir, name, suffix), "layer " + name + " of --layers"});
    };
    if (!plan) {
        image(a.input, a.occlusion.matte, a.output, "");
    } else {
        for (int f : plan->frames)
            image(plan->in.path(f), matte ? matte->path(f) : "", plan->out.path(f),
                  frameSuffix(*plan, {f, plan->in.path(f), plan->out.path(f)}));
    }
    return checkJobFiles(reads, writes);
}

//! The flare over black, pass by pass (written as layers when asked), then the output: the
//! flare alone, or the input plus exactly that flare. `passes` keeps the passes and the flare
//! when `keepPasses` (the output's channels, an in-memory caller's layers).
Status renderByLayers(const ApplyOptions& a, const Preset& preset, const Lights& lights,
                      const std::string& layerSuffix, LoadedImage& loaded,
                      std::vector<FlareLayer>& passes, bool keepPasses) {
    Image& image = loaded.image;
    Image flare;
    passes = renderFlareLayers(image.width(), image.height(), preset, lights, flare);
    if (!a.layersDir.empty()) {
        if (Status s = writeFlareLayers(a.layersDir, layerSuffix, passes, flare, a.encode); !s)
            return s;
    }
    if (a.flareOnly) {
        loaded.hasAlpha = false;
        if (keepPasses) passes.push_back({"flare", flare});
        image = std::move(flare);
        return Ok{};
    }
    float* dst = image.data();
    const float* add = flare.data();
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i)
        if (i % 4 != 3) dst[i] += add[i];
    if (keepPasses) passes.push_back({"flare", std::move(flare)});
    return Ok{};
}

//! An image already read (from `in`, for `out`; both only name it): its lights, their flares,
//! the display curve and the output's options. `passes`: each pass and the whole flare, kept
//! when `keepPasses` or the output carries them.
Result<ImageOutput> flareLoaded(const ApplyOptions& a, const Preset& preset, LoadedImage& loaded,
                                const std::string& in, const std::string& out,
                                const LightsOf& lightsOf, const JobEvents& events,
                                const std::string& layerSuffix, bool keepPasses,
                                std::vector<FlareLayer>& passes) {
    Image& image = loaded.image;
    auto flares = lightsOf(loaded);
    if (!flares) return flares.error();
    if (Status s =
            checkFlareWork(preset, image.width(), image.height(), int(flares->size()), a.preset);
        !s) {
        return s.error();
    }
    keepPasses = keepPasses || a.layersInOutput;
    if (!a.layersDir.empty() || a.flareOnly || keepPasses) {
        if (Status s = renderByLayers(a, preset, *flares, layerSuffix, loaded, passes, keepPasses);
            !s)
            return s.error();
    } else {
        for (const auto& [light, intensity] : *flares) {
            if (!(intensity > 0.f)) continue;
            const FlareStats stats = renderFlare(image, preset, light, intensity);
            if (a.verbose)
                events.say(
                    format("flare at %.1f,%.1f, intensity %.4f: %zu elements, %zu pixels "
                           "shaded",
                           double(light.x), double(light.y), double(intensity), stats.elementsDrawn,
                           stats.pixelsShaded));
        }
    }
    // No curve named: defaultDisplayCurve (filmic for HDR input to an 8/16-bit file). The flare
    // alone stays linear (it is added in the compositing package) unless a curve is named.
    const ToneOperator curve = a.tonemap.value_or(
        a.flareOnly ? ToneOperator::None : defaultDisplayCurve(loaded.wasFloat, out, a.depth));
    toneMapImage(image, curve, a.exposure);
    ImageOutput result{std::move(image), {}};
    result.options.alpha = loaded.hasAlpha;
    result.options.format = a.depth;
    result.options.encode = a.encode;
    // An EXR plate's other channels, attributes and windows go on to an EXR output (not to the
    // flare alone, which is not the plate).
    if (!a.flareOnly) result.options.exrExtras = keptExtras(loaded, in, out, events);
    if (a.layersInOutput) {
        std::vector<NamedLayer> named;
        for (const FlareLayer& pass : passes) named.push_back({pass.name, &pass.image});
        result.options.exrExtras = withLayerChannels(result.options.exrExtras, named);
    }
    if (a.color) a.color->toOutput(result.image, result.options);
    return result;
}

Result<ImageOutput> applyFlare(const ApplyOptions& a, const std::string& in, const std::string& out,
                               const LightsOf& lightsOf, const JobEvents& events,
                               const std::string& layerSuffix = "") {
    if (Status s = checkLayersFit(a.layersInOutput, out); !s) return s.error();
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    auto loaded = readJobInput(in, applyMemory(a, *preset), events, {a.part});
    if (!loaded) return loaded.error();
    // The flare alone is not the plate: its parts are not written with it.
    if (!a.flareOnly) {
        if (Status s = checkPartsFit(*loaded, in, out); !s) return s.error();
    }
    if (a.color) a.color->toWorking(*loaded);
    std::vector<FlareLayer> passes;
    return flareLoaded(a, *preset, *loaded, in, out, lightsOf, events, layerSuffix, false, passes);
}

//! One image's light: placed (measured there unless --flux-mode fixed) and dimmed by the
//! matte's coverage, or found.
Result<Lights> imageLights(const ApplyOptions& a, const std::string& in, const LoadedImage& plate,
                           std::optional<ShotCoverage>& coverage, const JobEvents& events) {
    if (!a.light) return autoLights(a, in, plate.image, events);
    float intensity = a.intensity;
    if (a.fluxMode == FluxMode::Measured) {
        const LightCandidate placed = measureLightAt(plate.image, *a.light, a.lightSearch);
        intensity *= placed.flareScale;
        if (placed.flux <= 0)
            events.warn(format(
                "--light %g,%g: nothing to measure there (%s): no flare; --flux-mode fixed draws "
                "the preset's own",
                double(a.light->x), double(a.light->y), placed.verdict.c_str()));
        if (a.verbose)
            events.say(format("placed light: flux %.4g, flare scale %.4f", placed.flux,
                              double(placed.flareScale)));
    }
    if (coverage) {
        auto row = coverage->at(0, plate);
        if (!row) return row.error();
        intensity *= float(row->raw);
        if (a.verbose) events.say(format("coverage %.4f", row->raw));
    }
    return Lights{{*a.light, intensity}};
}

//! One image: the light given or found, dimmed by the matte's coverage when one is given.
Status applyToImage(const ApplyOptions& a, const JobEvents& events) {
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    if (Status s = checkApplyFiles(a, *preset, nullptr, std::nullopt); !s) return s;
    std::optional<ShotCoverage> coverage;
    if (a.occlusion.enabled())
        coverage.emplace(
            a.occlusion, nullptr, a.occlusion.matte, [&](int) { return *a.light; }, events);
    return writeImageJob(a.output, [&] {
        return applyFlare(
            a, a.input, a.output,
            [&](const LoadedImage& plate) {
                return imageLights(a, a.input, plate, coverage, events);
            },
            events);
    });
}

//! What a shot's frames leave behind besides the images: coverage rows, the written track, the
//! frames where the followed light was not seen. Filled from several threads.
struct ShotRecords {
    std::mutex mutex;
    std::vector<CoverageRow> coverage;
    std::map<int, std::string> track;
    std::vector<int> unlit;
};

//! A frame pattern: every frame of the range, the light fixed, tracked, projected or followed,
//! its coverage filtered over the shot and written to coverage.csv.
Result<ShotSummary> applyToShot(const ApplyOptions& a, const JobEvents& events) {
    std::vector<FramePattern> otherInputs;
    std::optional<FramePattern> mattePattern;
    if (!a.occlusion.matte.empty()) {
        auto matte = parseFramePattern(a.occlusion.matte);
        if (!matte)
            return invalidInput("--matte " + a.occlusion.matte +
                                ": the input is a frame pattern, so the matte must be one "
                                "too (matte.####.exr)");
        otherInputs.push_back(*matte);
        mattePattern = *matte;
    }
    auto plan = planShot(a.input, a.output, a.shot, otherInputs, events);
    if (!plan) return plan.error();
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    if (Status s = checkApplyFiles(a, *preset, &*plan, mattePattern); !s) return s.error();
    auto light = ShotLight::load(a, *plan, events);
    if (!light) return light.error();
    auto parallel = framesInFlight(*plan, applyMemory(a, *preset), false);
    if (!parallel) return parallel.error();
    std::optional<ShotCoverage> coverage;
    if (a.occlusion.enabled())
        coverage.emplace(
            a.occlusion, &*plan, "", [&](int f) { return (*light)->position(f); }, events);
    ShotRecords records;
    auto lightsOf = [&](int frame, const LoadedImage& plate) -> Result<Lights> {
        auto weight = (*light)->weight(frame, plate.image);
        if (!weight) return weight.error();
        float intensity = a.intensity * weight->weight;
        const Point at = (*light)->position(frame, &plate.image);
        std::optional<CoverageRow> row;
        if (coverage) {
            auto measured = coverage->at(frame, plate);
            if (!measured) return measured.error();
            row = *measured;
            intensity *= float(row->filtered);
        }
        std::lock_guard lock(records.mutex);
        if (row) records.coverage.push_back(*row);
        if ((*light)->followsFinder() && !weight->present) records.unlit.push_back(frame);
        if (!a.writeTrack.empty() && weight->present)
            records.track[frame] = format("%d,%.9g,%.9g,%.9g", frame, double(at.x), double(at.y),
                                          double(weight->weight));
        return Lights{{at, intensity}};
    };
    auto summary = runShot(
        *plan, *parallel,
        [&](const ShotFrame& f) {
            return applyFlare(
                a, f.in, f.out, [&](const LoadedImage& plate) { return lightsOf(f.frame, plate); },
                events, frameSuffix(*plan, f));
        },
        events);
    if (!summary) return summary.error();
    if (!records.unlit.empty()) {
        std::sort(records.unlit.begin(), records.unlit.end());
        events.warn(a.input + ": no light found in frames " + describeFrames(records.unlit) +
                    " (written without a flare; --light X,Y or --light-track places one)");
    }
    if (coverage) {
        if (Status s = coverage->writeCsv(plan->outDir, records.coverage); !s) return s.error();
    }
    if (!a.writeTrack.empty()) {
        if (Status s = mergeCsvRows(a.writeTrack, "frame,x,y,intensity", records.track); !s)
            return s.error();
    }
    return summary;
}

//! The option combinations, checked before any file is read.
Status checkApplyOptions(const ApplyOptions& a) {
    if (a.light) {
        if (Status s = checkLightCoordinates(*a.light, "--light"); !s) return s;
    }
    // Before any work: writeImage would refuse it at the end.
    if (Status s = checkSampleFormatFits(a.output, a.depth, "--depth"); !s) return s;
    const int sources =
        int(a.light.has_value()) + int(!a.lightTrack.empty()) + int(!a.camera.empty());
    if (sources > 1)
        return invalidInput("--light X,Y, --light-track and --camera: give one of them");
    if (!a.camera.empty() && a.lightWorld.has_value() == a.sunDir.has_value())
        return invalidInput(
            "--camera needs the light: --light-world X,Y,Z (a point) or "
            "--sun-dir X,Y,Z (the direction toward the sun), one of them");
    if (a.camera.empty() && (a.lightWorld || a.sunDir))
        return invalidInput("--light-world/--sun-dir need --camera FILE");
    if (a.sunDir && !(length(*a.sunDir) > 0))
        return invalidInput("--sun-dir: expected X,Y,Z (three finite numbers, not all 0)");
    if (a.occlusion.enabled()) {
        if (Status s = checkOcclusionOptions(a.occlusion); !s) return s;
    }
    if (isFramePattern(a.input)) return Ok{};
    if (Status s = checkSingleImage(a.input, a.shot); !s) return s;
    for (const auto& [given, option] :
         {std::pair{a.lightTrack, "--light-track"}, std::pair{a.camera, "--camera"},
          std::pair{a.writeTrack, "--write-track"}})
        if (!given.empty())
            return invalidInput(std::string(option) +
                                ": the input is one image, not a frame pattern "
                                "(shot.####.exr) whose frames it keys");
    if (a.occlusion.enabled() && !a.light)
        return invalidInput(
            "--matte/--matte-channel/--depth-channel on one image "
            "need the light's position: --light X,Y");
    return Ok{};
}

}  // namespace

Result<JobReport> runApplyJob(const ApplyOptions& options, const JobEvents& events) {
    if (Status s = checkApplyOptions(options); !s) return s.error();
    JobReport report;
    report.sequence = isFramePattern(options.input);
    if (!report.sequence) {
        if (Status s = applyToImage(options, events); !s) return s.error();
        return report;
    }
    auto summary = applyToShot(options, events);
    if (!summary) return summary.error();
    report.shot = *summary;
    return report;
}

Result<PixelOutput> applyPixels(const ApplyOptions& options, PixelInput input,
                                const JobEvents& events, bool keepLayers) {
    auto preset = loadPreset(options.preset);
    if (!preset) return preset.error();
    return applyPixels(options, *preset, std::move(input), events, keepLayers);
}

Result<PixelOutput> applyPixels(const ApplyOptions& options, const Preset& preset, PixelInput input,
                                const JobEvents& events, bool keepLayers) {
    if (Status s = validatePreset(preset); !s)
        return invalidInput(options.preset + ": " + s.error().message);
    ApplyOptions a = options;
    a.layersDir.clear(), a.layersInOutput = false, a.color = nullptr;
    if (a.light) {
        if (Status s = checkLightCoordinates(*a.light, "--light"); !s) return s.error();
    }
    if (!a.lightTrack.empty() || !a.camera.empty() || a.occlusion.enabled())
        return invalidInput(
            "--light-track, --camera and --matte key files to a sequence's frames: run the "
            "file job for them");
    const std::string name = input.name;
    auto loaded = job_detail::loadedFromPixels(std::move(input), applyMemory(a, preset), events);
    if (!loaded) return loaded.error();
    std::optional<ShotCoverage> noCoverage;
    std::vector<FlareLayer> passes;
    auto out = flareLoaded(
        a, preset, *loaded, name, "",
        [&](const LoadedImage& plate) { return imageLights(a, name, plate, noCoverage, events); },
        events, "", keepLayers, passes);
    if (!out) return out.error();
    PixelOutput result{std::move(out->image), {}};
    for (FlareLayer& pass : passes) result.layers.push_back({pass.name, std::move(pass.image)});
    return result;
}

}  // namespace flarekit
