// SPDX-License-Identifier: Apache-2.0
// flarekit lens: flares from real lens prescriptions (presets/lenses). `ghosts` reports every
// two-reflection ghost of a distant point source, `render` puts the traced flare on an image,
// `list` names the shipped lenses with their paraxial figures.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "flarekit/Lens.h"
#include "flarekit/Tonemap.h"
#include "flarekit/job/LensJob.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/LensBackend.h"
#endif

namespace flarekit::cli {

namespace {

//! The options of list, ghosts, bake and sheet (render's are the library's LensJobOptions).
struct LensArgs {
    LensJobOptions lens;  //!< the lens and its f-number, as `render` takes them
    std::string angle = "0,0", out;
    bool json = false;
    LensToolOptions tool;
    LensRenderOptions render;
};

Result<Lens> openLens(const LensArgs& a) {
    return openJobLens(a.lens);
}

Result<std::array<double, 2>> parseAngle(const std::string& text) {
    const auto p = parsePoint(text);
    if (!p) return invalidInput("--angle: expected X,Y in degrees, got '" + text + "'");
    return std::array<double, 2>{p->x, p->y};
}

int runGhosts(const LensArgs& a) {
    auto lens = openLens(a);
    if (!lens) return report(lens.error());
    auto angle = parseAngle(a.angle);
    if (!angle) return report(angle.error());
    GhostQuery q;
    q.angleXDeg = (*angle)[0], q.angleYDeg = (*angle)[1], q.gridSide = a.tool.rays;
    q.ghostRays = a.tool.ghostRays;
    auto r = analyseGhosts(*lens, q);
    if (!r) return report(r.error());
    if (a.json) {
        std::printf("%s\n", ghostReportJson(lens->name, *r).c_str());
        return kExitOk;
    }
    std::printf("%s: f = %.3f mm, %zu ghosts at %g,%g degrees\n", lens->name.c_str(),
                r->focalLength, r->ghosts.size(), q.angleXDeg, q.angleYDeg);
    std::printf("%-8s %10s %10s %10s %8s %12s %12s %12s\n", "path", "x mm", "y mm", "r90 mm",
                "sensor", "R", "G", "B");
    // A ghost most of whose rays miss the sensor is marked: its centre is that of the part seen.
    const auto row = [](const std::string& name, const GhostFigure& g) {
        std::printf("%-8s %10.3f %10.3f %10.3f %7.0f%% %12.3e %12.3e %12.3e%s\n", name.c_str(),
                    g.centerX, g.centerY, g.radius90, 100 * g.onSensor, g.intensity[0],
                    g.intensity[1], g.intensity[2], g.onSensor < 0.5 ? "  mostly off sensor" : "");
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

int runBake(const LensArgs& a) {
    auto lens = openLens(a);
    if (!lens) return report(lens.error());
    auto preset = bakeLens(*lens, a.render.ghosts);
    if (!preset) return report(preset.error());
    const std::string text = presetToJson(*preset);
    // What is written must load as any preset does.
    if (auto check = parsePreset(text, a.out); !check)
        return report(internalError("baked preset does not read back: " + check.error().message));
    if (Status s = writeFileSafely(a.out, text); !s) return report(s.error());
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

    CLI::App* ghosts = lens->add_subcommand(
        "ghosts", "every two-reflection ghost of a distant point source, brightest first");
    addLensChoiceOptions(ghosts, args->lens);
    ghosts
        ->add_option("--angle", args->angle,
                     "field angle X,Y in degrees: rays travel along (tan X, tan Y, 1)")
        ->capture_default_str();
    addParamOption<LensToolOptions>(ghosts, kLensToolParams, "rays", args->tool);
    addParamOption<LensToolOptions>(ghosts, kLensToolParams, "ghost_rays", args->tool);
    ghosts->add_flag("--json", args->json, "print the report as JSON");
    ghosts->callback([args, &exitCode] { exitCode = runGhosts(*args); });

    CLI::App* bake = lens->add_subcommand(
        "bake", "compile the lens into a sprite preset (for apply, render and the engine API)");
    addLensChoiceOptions(bake, args->lens);
    bake->add_option("-o,--output", args->out, "preset JSON to write")->required();
    addParamOption<LensToolOptions>(bake, kLensToolParams, "ghosts", args->tool);
    bake->callback([args, &exitCode] {
        args->render.ghosts = args->tool.ghosts;
        exitCode = runBake(*args);
    });

    CLI::App* sheet = lens->add_subcommand(
        "sheet", "the lens in cross-section with its ghost paths, and its flare at three angles");
    addLensChoiceOptions(sheet, args->lens);
    sheet->add_option("-o,--output", args->out, "image to write")->required();
    addParamOption<LensToolOptions>(sheet, kLensToolParams, "width", args->tool);
    sheet->callback([args, &exitCode] {
        exitCode = runImageJob(args->out, [&]() -> Result<ImageOutput> {
            auto opened = openLens(*args);
            if (!opened) return opened.error();
            auto image = renderLensSheet(*opened, args->tool.sheetWidth);
            if (!image) return image.error();
            return ImageOutput{std::move(*image), {}};
        });
    });

    addLensRenderCommand(lens, exitCode);
}

}  // namespace flarekit::cli
