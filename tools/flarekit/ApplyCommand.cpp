// SPDX-License-Identifier: Apache-2.0
// flarekit apply: composite a preset's sprite flare onto an image, in linear light.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "ColorManagement.h"
#include "Common.h"
#include "ParamOptions.h"
#include "ShotCoverage.h"
#include "ShotRun.h"
#include "ShotTracking.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Temporal.h"
#include "flarekit/Tonemap.h"

namespace flarekit::cli {

namespace {
struct ApplyArgs {
    std::string in, out, preset = kDefaultSpritePreset, light = "auto", depth = "auto",
                         tonemap = "auto";
    float intensity = 1.f, exposure = 1.f;
    LightSearchOptions lightSearch;
    bool verbose = false;
    std::string lightTrack, layersDir, writeTrack, camera, lightWorld, sunDir;
    bool flareOnly = false;
    ShotArgs shot;
    OcclusionArgs occlusion;
    ColorArgs color;
    std::shared_ptr<const ColorManagement> colors;  //!< built from `color` before the run
};
inline constexpr Param<ApplyArgs> kApplyArgParams[] = {
    param<&ApplyArgs::intensity>("intensity", 0, 1000, "", "flare brightness multiplier"),
    param<&ApplyArgs::exposure>("exposure", 0, 1000, "",
                                "multiplies the image (flare included) before the display curve"),
};

//! Checked before any work: writeImage would refuse at the end (holdsFloatSamples).
Status checkDepthFits(const std::string& out, SampleFormat requested) {
    if (!isFloatFormat(requested) || holdsFloatSamples(out)) return Ok{};
    return invalidInput(out +
                        ": --depth half/float needs a float format (.exr, .tif, .hdr), not '" +
                        std::filesystem::path(out).extension().string() + "'");
}

std::optional<SampleFormat> parseDepth(const std::string& s) {
    if (s == "auto") return SampleFormat::Auto;
    if (s == "8") return SampleFormat::U8;
    if (s == "16") return SampleFormat::U16;
    if (s == "half") return SampleFormat::Half;
    if (s == "float") return SampleFormat::Float;
    return std::nullopt;
}

//! -v: every region --light auto considered, most flux first.
void printCandidates(const LightSearch& search) {
    std::vector<LightCandidate> sorted = search.candidates;
    std::stable_sort(
        sorted.begin(), sorted.end(),
        [](const LightCandidate& a, const LightCandidate& b) { return a.flux > b.flux; });
    std::printf(
        "peak luminance %.4g, median %.4g, %s; %zu candidates (most flux first, at most 12 "
        "listed):\n",
        double(search.peak), double(search.frameKey),
        search.displayReferred ? "display-referred (clipped pixels x clipped-gain)"
                               : "scene-referred HDR",
        sorted.size());
    //! Candidates listed at most: the lights and the closest misses, not every speck of sky.
    constexpr std::size_t kListed = 12;
    if (sorted.size() > kListed) sorted.resize(kListed);
    for (const LightCandidate& c : sorted)
        std::printf(
            "  at %.1f,%.1f radius %.1f px, peak %.4g, flux %.4g, %.2fx surroundings, "
            "compactness %.2f, halo %.2f, flare scale %.4f: %s\n",
            double(c.position.x), double(c.position.y), double(c.radius), double(c.peak), c.flux,
            double(c.prominence), double(c.compactness), double(c.halo), double(c.flareScale),
            c.verdict.c_str());
}

//! The lights of one frame, each a position and an intensity.
using Lights = std::vector<std::pair<Point, float>>;
using LightsOf = std::function<Result<Lights>(const LoadedImage&)>;

//! Measured peak (12 MP, both depths): ~135 MiB of process plus ~43 bytes per pixel: the RGBA
//! floats, the orientation copy, the encoded samples and the file bytes (plus the decode buffer,
//! which readImage adds).
const JobMemory kApplyMemory{40, 160.0 * (1 << 20), "apply: 40 bytes per pixel"};

//! --light auto: the lights the finder keeps in the frame, each scaled by its flare scale.
Result<Lights> autoLights(const ApplyArgs& a, const std::string& in, const Image& image) {
    const LightSearch search = findLights(image, a.lightSearch);
    if (a.verbose) printCandidates(search);
    if (search.lights.empty())
        warn(in + ": " + search.whyNone + "; image written unchanged (--light X,Y places one)");
    Lights lights;
    for (const LightCandidate& light : search.lights)
        lights.push_back({light.position, a.intensity * light.flareScale});
    return lights;
}

//! --layers: each pass and the whole flare as float EXRs in DIR, named NAME + `suffix` + .exr
//! (".1001" for a sequence's frame, so each pass is a sequence of its own).
Status writeFlareLayers(const std::string& dir, const std::string& suffix,
                        const std::vector<FlareLayer>& layers, const Image& flare) {
    if (Status s = makeOutputDirectory(dir); !s) return s;
    WriteOptions linear;
    linear.format = SampleFormat::Float;
    auto path = [&](const std::string& name) {
        return (std::filesystem::path(dir) / (name + suffix + ".exr")).string();
    };
    for (const FlareLayer& layer : layers)
        if (Status s = writeImage(path(layer.name), layer.image, linear); !s) return s;
    return writeImage(path("flare"), flare, linear);
}

Result<ImageOutput> applyFlare(const ApplyArgs& a, const std::string& in, const std::string& out,
                               const LightsOf& lightsOf, const std::string& layerSuffix = "") {
    const SampleFormat depth = *parseDepth(a.depth);
    if (Status s = checkDepthFits(out, depth); !s) return s.error();
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    auto loaded = readInputImage(in, kApplyMemory);
    if (!loaded) return loaded.error();
    if (a.colors) a.colors->toWorking(*loaded);
    Image& image = loaded->image;
    auto flares = lightsOf(*loaded);
    if (!flares) return flares.error();
    if (Status s =
            checkFlareWork(*preset, image.width(), image.height(), int(flares->size()), a.preset);
        !s) {
        return s.error();
    }
    if (!a.layersDir.empty() || a.flareOnly) {
        // The flare over black, pass by pass; the composite is the input plus exactly that.
        Image flare;
        const auto layers =
            renderFlareLayers(image.width(), image.height(), *preset, *flares, flare);
        if (!a.layersDir.empty()) {
            if (Status s = writeFlareLayers(a.layersDir, layerSuffix, layers, flare); !s)
                return s.error();
        }
        if (a.flareOnly) {
            loaded->hasAlpha = false;
            image = std::move(flare);
        } else {
            float* dst = image.data();
            const float* add = flare.data();
            for (std::size_t i = 0; i < image.pixelCount() * 4; ++i)
                if (i % 4 != 3) dst[i] += add[i];
        }
    } else {
        for (const auto& [light, intensity] : *flares) {
            if (!(intensity > 0.f)) continue;
            const FlareStats stats = renderFlare(image, *preset, light, intensity);
            if (a.verbose)
                std::printf("flare at %.1f,%.1f, intensity %.4f: %zu elements, %zu pixels shaded\n",
                            double(light.x), double(light.y), double(intensity),
                            stats.elementsDrawn, stats.pixelsShaded);
        }
    }
    // --tonemap auto: defaultDisplayCurve (filmic for HDR input to an 8/16-bit file).
    // --flare-only stays linear (it is added in the compositing package) unless a curve is named.
    const ToneOperator curve = namedToneOperator(a.tonemap).value_or(
        a.flareOnly ? ToneOperator::None : defaultDisplayCurve(loaded->wasFloat, out, depth));
    toneMapImage(image, curve, a.exposure);
    ImageOutput result{std::move(image), {}};
    result.options.alpha = loaded->hasAlpha;
    result.options.format = depth;
    // An EXR plate's other channels, attributes and windows go on to an EXR output (not to the
    // flare alone, which is not the plate).
    if (!a.flareOnly) result.options.exrExtras = keptExtras(*loaded, in, out);
    if (a.colors) a.colors->toOutput(result.image, result.options);
    return result;
}

//! One image: the light given or found, dimmed by the matte's coverage when one is given.
int runApplyImage(const ApplyArgs& a, const std::optional<Point>& fixed) {
    if (!a.lightTrack.empty())
        return report(
            invalidInput("--light-track: the input is one image, not a frame pattern "
                         "(shot.####.exr) whose frames the track keys"));
    std::optional<ShotCoverage> coverage;
    if (a.occlusion.enabled())
        coverage.emplace(a.occlusion, nullptr, a.occlusion.matte, [&](int) { return *fixed; });
    return runImageJob(a.out, [&] {
        return applyFlare(a, a.in, a.out, [&](const LoadedImage& plate) -> Result<Lights> {
            if (!fixed) return autoLights(a, a.in, plate.image);
            float intensity = a.intensity;
            if (coverage) {
                auto row = coverage->at(0, plate);
                if (!row) return row.error();
                intensity *= float(row->raw);
                if (a.verbose) std::printf("coverage %.4f\n", row->raw);
            }
            return Lights{{*fixed, intensity}};
        });
    });
}

//! Where a shot's light is per frame and how strong, from whichever source was given: a fixed
//! point, a track, a camera with a light in the world (or the sun's direction), or the light
//! the finder follows (--light auto).
struct ShotLight {
    std::optional<Point> fixed;
    std::optional<LightTrack> track;
    std::optional<CameraTrack> camera;
    Vec3 world;
    bool sun = false;
    double guardBand = 0.08;
    std::optional<ShotTracking> tracking;
    const ShotPlan* plan = nullptr;

    Point position(int frame, const Image* image = nullptr) {
        if (fixed) return *fixed;
        if (track) return track->at(frame).position;
        if (camera) {
            Point p;
            projectLight(camera->at(frame), plan->width, plan->height, world, sun, p);
            return p;
        }
        auto t = tracking->at(frame, image);
        return t ? t->position : Point{};
    }
    //! The intensity multiplier: the track's, the edge fade of a projected light, the followed
    //! light's flare scale. `present` false: no light this frame (behind the camera, or the
    //! followed light not seen).
    struct Weight {
        float weight = 1;
        bool present = true;
    };
    Result<Weight> weight(int frame, const Image& image) {
        if (track) return Weight{track->at(frame).intensity, true};
        if (camera) {
            Point p;
            if (!projectLight(camera->at(frame), plan->width, plan->height, world, sun, p))
                return Weight{0, false};
            return Weight{float(edgeFade(p, plan->width, plan->height, guardBand)), true};
        }
        if (tracking) {
            auto t = tracking->at(frame, &image);
            if (!t) return t.error();
            return Weight{t->found ? t->flareScale : 0.f, t->found};
        }
        return Weight{};
    }
};

std::optional<Vec3> parseVec3(const std::string& text) {
    double v[3];
    char end = 0;
    if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &end) != 3)
        return std::nullopt;
    for (double c : v)
        if (!std::isfinite(c)) return std::nullopt;
    return Vec3{v[0], v[1], v[2]};
}

//! The light sources given for a shot, loaded and checked before any frame.
Status loadShotLight(const ApplyArgs& a, const std::optional<Point>& fixed, const ShotPlan& plan,
                     ShotLight& light) {
    light.plan = &plan;
    light.fixed = fixed;
    light.guardBand = a.occlusion.temporal.guardBand;
    auto warnHeld = [&](const std::string& file, const std::vector<int>& held, double first,
                        double last) {
        if (held.empty()) return;
        char range[80];
        std::snprintf(range, sizeof range, " are outside the keys (%g to %g): ", first, last);
        warn(file + ": frames " + describeFrames(held) + range + "the end keys are held");
    };
    if (!a.lightTrack.empty()) {
        auto loaded = loadLightTrack(a.lightTrack);
        if (!loaded) return loaded.error();
        light.track = std::move(*loaded);
        std::vector<int> held;
        for (int f : plan.frames)
            if (light.track->at(f).held) held.push_back(f);
        warnHeld(a.lightTrack, held, light.track->keys.front().frame,
                 light.track->keys.back().frame);
    } else if (!a.camera.empty()) {
        const std::string& given = a.sunDir.empty() ? a.lightWorld : a.sunDir;
        const auto v = parseVec3(given);
        if (!v || (!a.sunDir.empty() && length(*v) <= 0))
            return invalidInput(std::string(a.sunDir.empty() ? "--light-world" : "--sun-dir") +
                                ": expected X,Y,Z (three finite numbers" +
                                (a.sunDir.empty() ? "" : ", not all 0") + "), got '" + given + "'");
        auto loaded = loadCameraTrack(a.camera);
        if (!loaded) return loaded.error();
        light.camera = std::move(*loaded);
        light.world = a.sunDir.empty() ? *v : normalize(*v);
        light.sun = !a.sunDir.empty();
        std::vector<int> held;
        for (int f : plan.frames) {
            bool h = false;
            light.camera->at(f, &h);
            if (h) held.push_back(f);
        }
        warnHeld(a.camera, held, light.camera->keys.front().frame, light.camera->keys.back().frame);
    } else if (!fixed) {
        light.tracking.emplace(plan, a.lightSearch);
    }
    return Ok{};
}

//! A frame pattern: every frame of the range, the light fixed, tracked, projected or followed,
//! its coverage filtered over the shot and written to coverage.csv.
int runApplyShot(const ApplyArgs& a, const std::optional<Point>& fixed) {
    std::vector<FramePattern> otherInputs;
    if (!a.occlusion.matte.empty()) {
        auto matte = parseFramePattern(a.occlusion.matte);
        if (!matte)
            return report(invalidInput("--matte " + a.occlusion.matte +
                                       ": the input is a frame pattern, so the matte must be one "
                                       "too (matte.####.exr)"));
        otherInputs.push_back(*matte);
    }
    auto plan = planShot(a.in, a.out, a.shot, otherInputs);
    if (!plan) return report(plan.error());
    ShotLight light;
    if (Status s = loadShotLight(a, fixed, *plan, light); !s) return report(s.error());
    auto parallel = framesInFlight(*plan, kApplyMemory, false);
    if (!parallel) return report(parallel.error());
    std::optional<ShotCoverage> coverage;
    if (a.occlusion.enabled())
        coverage.emplace(a.occlusion, &*plan, "", [&](int f) { return light.position(f); });
    std::mutex rowsMutex;
    std::vector<CoverageRow> rows;
    std::map<int, std::string> trackRows;
    std::vector<int> unlit;  // --light auto: frames where the followed light was not seen
    const int code = runShot(*plan, "apply", *parallel, [&](const ShotFrame& f) {
        return applyFlare(
            a, f.in, f.out,
            [&](const LoadedImage& plate) -> Result<Lights> {
                const Image& image = plate.image;
                auto weight = light.weight(f.frame, image);
                if (!weight) return weight.error();
                float intensity = a.intensity * weight->weight;
                const Point at = light.position(f.frame, &image);
                if (coverage) {
                    auto row = coverage->at(f.frame, plate);
                    if (!row) return row.error();
                    intensity *= float(row->filtered);
                    std::lock_guard lock(rowsMutex);
                    rows.push_back(*row);
                }
                if (light.tracking && !weight->present) {
                    std::lock_guard lock(rowsMutex);
                    unlit.push_back(f.frame);
                }
                if (!a.writeTrack.empty() && weight->present) {
                    char line[160];
                    std::snprintf(line, sizeof line, "%d,%.9g,%.9g,%.9g", f.frame, double(at.x),
                                  double(at.y), double(weight->weight));
                    std::lock_guard lock(rowsMutex);
                    trackRows[f.frame] = line;
                }
                return Lights{{at, intensity}};
            },
            frameSuffix(*plan, f));
    });
    if (code != kExitOk) return code;
    if (!unlit.empty()) {
        std::sort(unlit.begin(), unlit.end());
        warn(a.in + ": no light found in frames " + describeFrames(unlit) +
             " (written without a flare; --light X,Y or --light-track places one)");
    }
    if (coverage) {
        if (Status s = coverage->writeCsv(plan->outDir, rows); !s) return report(s.error());
    }
    if (!a.writeTrack.empty()) {
        if (Status s = mergeCsvRows(a.writeTrack, "frame,x,y,intensity", trackRows); !s)
            return report(s.error());
    }
    return code;
}

int runApply(const ApplyArgs& args) {
    ApplyArgs a = args;
    auto colors = ColorManagement::create(a.color);
    if (!colors) return report(colors.error());
    a.colors = *colors;
    const bool autoLight = a.light == "auto";
    const std::optional<Point> fixed = autoLight ? std::nullopt : parsePoint(a.light);
    if (!autoLight && !fixed)
        return report(
            invalidInput("--light: expected X,Y in pixels or 'auto', got '" + a.light + "'"));
    const int sources =
        int(fixed.has_value()) + int(!a.lightTrack.empty()) + int(!a.camera.empty());
    if (sources > 1)
        return report(invalidInput("--light X,Y, --light-track and --camera: give one of them"));
    if (!a.camera.empty() && a.lightWorld.empty() == a.sunDir.empty())
        return report(
            invalidInput("--camera needs the light: --light-world X,Y,Z (a point) or "
                         "--sun-dir X,Y,Z (the direction toward the sun), one of them"));
    if (a.camera.empty() && (!a.lightWorld.empty() || !a.sunDir.empty()))
        return report(invalidInput("--light-world/--sun-dir need --camera FILE"));
    if (a.occlusion.enabled()) {
        if (Status s = checkOcclusionArgs(a.occlusion); !s) return report(s.error());
    }
    if (!isFramePattern(a.in)) {
        if (Status s = checkSingleImage(a.in, a.shot); !s) return report(s.error());
        for (const auto& [given, option] :
             {std::pair{a.lightTrack, "--light-track"}, std::pair{a.camera, "--camera"},
              std::pair{a.writeTrack, "--write-track"}})
            if (!given.empty())
                return report(invalidInput(std::string(option) +
                                           ": the input is one image, not a frame pattern "
                                           "(shot.####.exr) whose frames it keys"));
        if (a.occlusion.enabled() && !fixed)
            return report(
                invalidInput("--matte/--matte-channel/--depth-channel on one image "
                             "need the light's position: --light X,Y"));
    }
    return isFramePattern(a.in) ? runApplyShot(a, fixed) : runApplyImage(a, fixed);
}
}  // namespace

void addApplyCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ApplyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Put a sprite lens flare on an image (linear-light additive compositing)");
    cmd->add_option("input", args->in,
                    "input image (EXR, PNG, JPEG, TIFF, ...; 8-bit files are sRGB-decoded), or a "
                    "frame pattern (shot.####.exr, shot.%04d.exr) for a sequence")
        ->required();
    cmd->add_option("-o,--output", args->out,
                    "output image (a frame pattern for a sequence); format and bit depth follow "
                    "the extension")
        ->required();
    cmd->add_option("--preset", args->preset,
                    "shipped preset name (see `flarekit presets`) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--light", args->light,
                    "light position X,Y in pixels from the top-left (may be outside the frame), or "
                    "'auto' for the "
                    "brightest region")
        ->capture_default_str();
    addParamOptions<ApplyArgs>(cmd, kApplyArgParams, *args);
    addParamOptions<LightSearchOptions>(cmd, kLightSearchParams, args->lightSearch);
    cmd->add_option("--depth", args->depth,
                    "output samples: auto (from the extension), 8, 16, half, float")
        ->check(CLI::IsMember({"auto", "8", "16", "half", "float"}))
        ->capture_default_str();
    cmd->add_option("--tonemap", args->tonemap,
                    "display curve: auto (filmic for HDR input to an 8/16-bit file, else none), "
                    "none, aces, filmic")
        ->check(CLI::IsMember(toneChoices({"auto"})))
        ->capture_default_str();
    cmd->add_option("--layers", args->layersDir,
                    "also write the flare over black (flare.exr: linear, unclamped, float) and "
                    "its passes (glow, halo, ghosts, streaks, starburst: those the preset has) "
                    "into DIR; the output is then exactly input + flare; for a sequence "
                    "DIR/flare.1001.exr, ...");
    cmd->add_flag("--flare-only", args->flareOnly,
                  "write the flare alone over black (linear unless --tonemap names a curve), to "
                  "add or screen over the plate in the compositing package");
    cmd->add_option("--write-track", args->writeTrack,
                    "a sequence: save where the light was each frame (CSV frame,x,y,intensity, "
                    "what --light-track reads), to edit and feed back; merged with the rows "
                    "other chunks wrote");
    cmd->add_option("--camera", args->camera,
                    "a sequence: the camera per frame (JSON: {\"frames\": [{\"frame\": 1001, "
                    "\"position\", \"look_at\", \"up\", \"fov_y_deg\"}, ...]}, a scene's "
                    "camera form), with --light-world or --sun-dir: the light projected each "
                    "frame; none behind the camera, faded over --guard-band at the frame's edge");
    cmd->add_option("--light-world", args->lightWorld, "with --camera: the light's point X,Y,Z");
    cmd->add_option("--sun-dir", args->sunDir,
                    "with --camera: the direction X,Y,Z toward a distant light (the sun)");
    cmd->add_option("--light-track", args->lightTrack,
                    "the light per frame of a sequence: CSV (frame,x,y or frame,x,y,intensity; "
                    "pixels from the top-left, centres at +0.5) or JSON; linear between keys, the "
                    "end keys held outside them");
    addShotOptions(cmd, args->shot);
    addOcclusionOptions(cmd, args->occlusion);
    addColorOptions(cmd, args->color);
    cmd->add_flag("-v,--verbose", args->verbose,
                  "print every light candidate (position, radius, flux, score) and the work done");
    cmd->callback([args, &exitCode] { exitCode = runApply(*args); });
}

}  // namespace flarekit::cli
