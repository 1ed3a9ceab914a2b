// SPDX-License-Identifier: Apache-2.0
// flarekit lens: flares from real lens prescriptions (presets/lenses). `ghosts` reports every
// two-reflection ghost of a distant point source, `render` puts the traced flare on an image,
// `list` names the shipped lenses with their paraxial figures.
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "Progress.h"
#include "flarekit/Lens.h"
#include "flarekit/Tonemap.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/GpuLens.h"
#endif

namespace flarekit::cli {

namespace {

struct LensArgs {
    std::string lens, angle = "0,0", in, out, light = "auto", layersDir, backend = "cpu",
                      tonemap = "auto", dirtFile;
    bool json = false, verbose = false;
    int rays = 64;
    double fNumber = 0, threshold = 2.0, expandGain = 64.0;
    int maxSources = 32, bakeGhosts = 16, sheetWidth = 1600;
    LensRenderOptions render;
    ShotOptions shot;
};

Result<Lens> openLens(const LensArgs& a) {
    auto lens = loadLens(a.lens);
    if (!lens) return lens;
    if (a.fNumber > 0) return stopDown(*lens, a.fNumber);
    return lens;
}

Result<std::array<double, 2>> parseAngle(const std::string& text) {
    const auto p = parsePoint(text);
    if (!p) return invalidInput("--angle: expected X,Y in degrees, got '" + text + "'");
    return std::array<double, 2>{p->x, p->y};
}

nlohmann::json figureJson(const GhostFigure& g) {
    nlohmann::json j;
    if (g.first >= 0) j["surfaces"] = {g.first, g.second};
    j["center"] = {g.centerX, g.centerY};
    j["radius_mm"] = g.radius;
    j["intensity"] = {g.intensity[0], g.intensity[1], g.intensity[2]};
    return j;
}

int runGhosts(const LensArgs& a) {
    auto lens = openLens(a);
    if (!lens) return report(lens.error());
    auto angle = parseAngle(a.angle);
    if (!angle) return report(angle.error());
    GhostQuery q;
    q.angleXDeg = (*angle)[0], q.angleYDeg = (*angle)[1], q.gridSide = a.rays;
    auto r = analyseGhosts(*lens, q);
    if (!r) return report(r.error());
    if (a.json) {
        nlohmann::json j;
        j["lens"] = lens->name;
        j["focal_length_mm"] = r->focalLength;
        j["direct"] = figureJson(r->direct);
        j["ghosts"] = nlohmann::json::array();
        for (const GhostFigure& g : r->ghosts) j["ghosts"].push_back(figureJson(g));
        std::printf("%s\n", j.dump(1).c_str());
        return kExitOk;
    }
    std::printf("%s: f = %.3f mm, %zu ghosts at %g,%g degrees\n", lens->name.c_str(),
                r->focalLength, r->ghosts.size(), q.angleXDeg, q.angleYDeg);
    std::printf("%-8s %10s %10s %10s %12s %12s %12s\n", "path", "x mm", "y mm", "radius mm", "R",
                "G", "B");
    const auto row = [](const std::string& name, const GhostFigure& g) {
        std::printf("%-8s %10.3f %10.3f %10.3f %12.3e %12.3e %12.3e\n", name.c_str(), g.centerX,
                    g.centerY, g.radius, g.intensity[0], g.intensity[1], g.intensity[2]);
    };
    row("direct", r->direct);
    for (const GhostFigure& g : r->ghosts)
        row(std::to_string(g.first) + "," + std::to_string(g.second), g);
    return kExitOk;
}

int runList() {
    std::printf("%-26s %9s %7s %8s  %s\n", "lens", "f mm", "F/", "surfaces", "source");
    for (const std::string& name : lensNames()) {
        auto lens = loadLens(name);
        if (!lens) return report(lens.error());
        const Paraxial p = paraxial(*lens);
        std::printf("%-26s %9.3f %7.2f %8zu  %s\n", name.c_str(), p.focalLength, p.fNumber,
                    lens->surfaces.size(), excerptLine(lens->source, 60).c_str());
    }
    return kExitOk;
}

//! The render's peak per pixel: the input, the three layers, their sum and the composite.
JobMemory lensRenderMemory() {
    return {6 * 16.0, 256.0 * (1 << 20), "lens render: 96 bytes per pixel and the traced meshes"};
}

Result<std::vector<LensLight>> findLights(const LensArgs& a, const Image& image) {
    const int diagonal = int(std::hypot(double(image.width()), double(image.height())));
    if (a.light == "all")
        return brightSources(image, a.threshold, std::max(1, diagonal / 64), a.maxSources);
    if (a.light == "auto") {
        // The brightest region: bright pixels merged over cells a sixteenth of the diagonal.
        auto lights = brightSources(image, a.threshold, std::max(1, diagonal / 16), 1);
        if (lights.empty())
            warn(a.in + ": no pixel at or above --threshold " + std::to_string(a.threshold) +
                 ": no light, no flare");
        return lights;
    }
    const auto p = parsePoint(a.light);
    if (!p)
        return invalidInput("--light: expected X,Y in pixels, auto or all, got '" + a.light + "'");
    // Its energy: the bright pixels within a 32nd of the diagonal.
    LensLight l = sourceAt(image, p->x, p->y, diagonal / 32.0, a.threshold);
    if (l.energy[0] + l.energy[1] + l.energy[2] <= 0) {
        warn(a.in + ": nothing at or above --threshold near " + a.light +
             ": the light is given the energy of a 100-pixel source of 100 x white");
        l.energy = {1e4, 1e4, 1e4};
    }
    return std::vector<LensLight>{l};
}

//! The flare's layers through the chosen backend.
Result<LensFlareLayers> renderLayers(const LensArgs& a, const Lens& lens, const Image& image,
                                     const std::vector<LensLight>& lights) {
    // Many sources take minutes: a bar on a terminal, otherwise (logs, a farm) a line per source.
    LensRenderOptions render = a.render;
    std::optional<Progress> bar;
    if (lights.size() > 1) {
        if (isatty(fileno(stderr)) == 1) bar.emplace("lens render", int(lights.size()));
        render.progress = [&](int done, int total) {
            if (bar) {
                bar->update(done);
                if (done == total) bar->finish();
            } else {
                std::fprintf(stderr, "lens render: %s: source %d of %d drawn\n", a.in.c_str(), done,
                             total);
            }
            return true;
        };
    }
    if (a.backend == "cpu")
        return renderLensFlare(lens, image.width(), image.height(), lights, render);
#if FLAREKIT_HAS_GL
    auto context = createHeadlessGl();
    if (!context) return context.error();
    if (Status s = checkGlFrame(image.width(), image.height(), 1, a.in + ": image"); !s)
        return s.error();
    LensGlTimes times;
    auto layers = renderLensFlareGl(lens, image.width(), image.height(), lights, render, &times);
    if (layers && a.verbose)
        std::printf("OpenGL: %s: ghosts %.2f GPU ms, read-back %.2f ms\n",
                    (*context)->renderer().c_str(), times.ghostsGpuMs, times.readbackMs);
    return layers;
#else
    (void)lens, (void)lights;
    return builtWithoutGl("lens render --backend gl");
#endif
}

//! One image (a sequence's frame) `in` for `out`; the layers as DIR/NAME + `layerSuffix` + .exr.
Result<ImageOutput> renderJob(const LensArgs& a, const std::string& in, const std::string& out,
                              const std::string& layerSuffix = "") {
#if !FLAREKIT_HAS_GL
    // Before any work: a build without OpenGL says so at once.
    if (a.backend == "gl") return builtWithoutGl("lens render --backend gl");
#endif
    auto lens = openLens(a);
    if (!lens) return lens.error();
    auto loaded = readJobInput(in, lensRenderMemory(), warningEvents());
    if (!loaded) return loaded.error();
    Image& image = loaded->image;
    // 8/16-bit photographs clip their lights at 1: expand them back (postfx's inverse curve) so
    // a clipped sun carries the energy a flare needs; the output keeps the original pixels.
    const bool expand = !loaded->wasFloat && a.expandGain > 1.0;
    Image expanded;
    if (expand) {
        expanded = image;
        expandHighlights(expanded, float(a.expandGain));
    }
    auto lights = findLights(a, expand ? expanded : image);
    if (!lights) return lights.error();
    auto layers = renderLayers(a, *lens, image, *lights);
    if (!layers) return layers.error();
    // The flare layer: the three parts' colour, opaque like each of them.
    Image flare(image.width(), image.height());
    for (std::size_t i = 0; i < flare.pixelCount() * 4; ++i)
        flare.data()[i] = i % 4 == 3 ? 1.f
                                     : layers->ghosts.data()[i] + layers->starburst.data()[i] +
                                           layers->glare.data()[i];
    if (!a.layersDir.empty()) {
        if (Status s = makeOutputDirectory(a.layersDir); !s) return s.error();
        const auto path = [&](const char* n) {
            return (std::filesystem::path(a.layersDir) / (n + layerSuffix + ".exr")).string();
        };
        for (const auto& [name, img] :
             {std::pair{"ghosts", &layers->ghosts}, std::pair{"starburst", &layers->starburst},
              std::pair{"glare", &layers->glare}, std::pair{"flare", &flare}}) {
            if (Status s = writeImage(path(name), *img); !s) return s.error();
        }
    }
    Image composite = image;
    for (std::size_t i = 0; i < composite.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) composite.data()[4 * i + c] += flare.data()[4 * i + c];
    }
    ToneOperator op = defaultDisplayCurve(loaded->wasFloat, out);
    if (const auto named = toneOperatorNamed(a.tonemap)) op = *named;
    toneMapImage(composite, op, 1.f);
    ImageOutput result{std::move(composite), {}};
    result.options.alpha = loaded->hasAlpha;
    std::printf("%s: %zu light(s), flare through %s (f = %.1f mm)\n", out.c_str(), lights->size(),
                lens->name.c_str(), paraxial(*lens).focalLength);
    return result;
}

//! One image, or every frame of a pattern (the layers then as DIR/ghosts.1001.exr, ...).
int runRender(const LensArgs& given) {
    LensArgs a = given;
    if (!a.dirtFile.empty()) {
        // Read once, for every frame of a sequence.
        auto mask = readImage(a.dirtFile, {16.0, 0.0, "--dirt-file: 16 bytes per pixel"});
        if (!mask) return report(mask.error());
        a.render.pupilMask = std::make_shared<const Image>(std::move(mask->image));
    }
    if (!isFramePattern(a.in)) return runImageJob(a.out, [&] { return renderJob(a, a.in, a.out); });
    CliRun run("lens render");
    auto plan = planShot(a.in, a.out, a.shot, {}, run.events());
    if (!plan) return report(plan.error());
    auto parallel = framesInFlight(*plan, lensRenderMemory(), a.backend == "gl");
    if (!parallel) return report(parallel.error());
    return run.finish(runShot(
        *plan, *parallel,
        [&](const ShotFrame& f) { return renderJob(a, f.in, f.out, frameSuffix(*plan, f)); },
        run.events()));
}

int runBake(const LensArgs& a) {
    auto lens = openLens(a);
    if (!lens) return report(lens.error());
    auto preset = bakeLens(*lens, a.render.ghosts);
    if (!preset) return report(preset.error());
    const std::string text = presetToJson(*preset);
    // What is written must load as any preset does.
    if (auto check = parsePreset(text, a.out); !check)
        return report(internalError("baked preset does not read back: " + check.error().message));
    if (Status s = writeText(a.out, text); !s) return report(s.error());
    std::printf("%s: %zu elements baked from %s\n", a.out.c_str(), preset->elements.size(),
                lens->name.c_str());
    return kExitOk;
}

}  // namespace

void addLensCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<LensArgs>();
    CLI::App* lens = app.add_subcommand(
        "lens",
        "Flares from real lens prescriptions (presets/lenses): traced ghosts, coatings, "
        "dispersion, the aperture's starburst");
    lens->require_subcommand(1);

    CLI::App* list = lens->add_subcommand("list", "the shipped lenses and their paraxial figures");
    list->callback([&exitCode] { exitCode = runList(); });

    const auto addLensOptions = [&](CLI::App* cmd) {
        cmd->add_option("lens", args->lens, "lens prescription: a shipped name or a JSON file")
            ->required();
        cmd->add_option("--f-number", args->fNumber,
                        "stop the lens down to this working f-number (paraxial)")
            ->check(CLI::Range(0.1, 1000.0));
    };
    CLI::App* ghosts = lens->add_subcommand(
        "ghosts", "every two-reflection ghost of a distant point source, brightest first");
    addLensOptions(ghosts);
    ghosts
        ->add_option("--angle", args->angle,
                     "field angle X,Y in degrees: rays travel along (tan X, tan Y, 1)")
        ->capture_default_str();
    ghosts->add_option("--rays", args->rays, "rays per side over the first clear aperture")
        ->check(CLI::Range(2, 1024))
        ->capture_default_str();
    ghosts->add_flag("--json", args->json, "print the report as JSON");
    ghosts->callback([args, &exitCode] { exitCode = runGhosts(*args); });

    CLI::App* bake = lens->add_subcommand(
        "bake", "compile the lens into a sprite preset (for apply, render and the engine API)");
    addLensOptions(bake);
    bake->add_option("-o,--output", args->out, "preset JSON to write")->required();
    bake->add_option("--ghosts", args->bakeGhosts, "the brightest N ghosts baked")
        ->check(CLI::Range(1, 254))
        ->capture_default_str();
    bake->callback([args, &exitCode] {
        args->render.ghosts = args->bakeGhosts;
        exitCode = runBake(*args);
    });

    CLI::App* sheet = lens->add_subcommand(
        "sheet", "the lens in cross-section with its ghost paths, and its flare at three angles");
    addLensOptions(sheet);
    sheet->add_option("-o,--output", args->out, "image to write")->required();
    sheet->add_option("--width", args->sheetWidth, "sheet width in pixels (height: 9/16 of it)")
        ->check(CLI::Range(320, 8192))
        ->capture_default_str();
    sheet->callback([args, &exitCode] {
        exitCode = runImageJob(args->out, [&]() -> Result<ImageOutput> {
            auto opened = openLens(*args);
            if (!opened) return opened.error();
            auto image = renderLensSheet(*opened, args->sheetWidth);
            if (!image) return image.error();
            return ImageOutput{std::move(*image), {}};
        });
    });

    CLI::App* render = lens->add_subcommand("render", "the lens's flare on an image");
    // Photographs and HDRIs clip the sun by orders of magnitude (a real one is ~10^5 x the sky),
    // so the command draws ghosts 100 x their physical share by default; --ghost-gain 1 is the
    // lens's own figure for an unclipped source.
    args->render.ghostGain = 100;
    addLensOptions(render);
    render
        ->add_option("input", args->in,
                     "input image (EXR kept linear; 8-bit files sRGB), or a frame pattern "
                     "(shot.####.exr) for a sequence")
        ->required();
    render->add_option("-o,--output", args->out, "output image")->required();
    render
        ->add_option("--light", args->light,
                     "X,Y in pixels, auto (the brightest region) or all (every bright area "
                     "is a source, merged on a grid)")
        ->capture_default_str();
    render
        ->add_option("--threshold", args->threshold,
                     "linear luminance at which a pixel is a source")
        ->check(CLI::Range(0.0, 1e12))
        ->capture_default_str();
    render->add_option("--max-sources", args->maxSources, "--light all: at most N sources")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    render
        ->add_option("--expand-highlights", args->expandGain,
                     "8/16-bit input: clipped pixels count as GAIN x white as sources")
        ->check(CLI::Range(1.0, 1e6))
        ->capture_default_str();
    render->add_option("--layers", args->layersDir,
                       "also write ghosts, starburst, glare and flare (their sum) as linear EXR "
                       "into DIR");
    render
        ->add_option("--backend", args->backend,
                     "cpu, or gl: the ghost meshes rasterised by OpenGL 4.5 (headless EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    render
        ->add_option("--tonemap", args->tonemap,
                     "display curve for 8/16-bit outputs: auto (filmic for HDR input), none, "
                     "aces, filmic")
        ->check(CLI::IsMember(toneChoices({"auto"})))
        ->capture_default_str();
    render->add_option("--dirt-file", args->dirtFile,
                       "the iris plane's transmission from an image (your dust, scratches or "
                       "aperture shape): luminance 1 clear, 0 opaque, stretched over the stop; "
                       "it shapes the starburst");
    render->add_flag("-v,--verbose", args->verbose,
                     "--backend gl: print the GPU and read-back times");
    for (const auto& p : kLensRenderParams) addParamOption(render, p, args->render);
    addShotOptions(render, args->shot);
    render->callback([args, &exitCode] { exitCode = runRender(*args); });
}

}  // namespace flarekit::cli
