// SPDX-License-Identifier: Apache-2.0
// flarekit lens render: the library's lens job (flarekit/job/LensJob.h) from the command line.
#include <memory>
#include <span>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "flarekit/job/LensJob.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/LensBackend.h"
#endif

namespace flarekit::cli {

namespace {
//! The words of `lens render` that the library takes typed.
struct RenderText {
    std::string light = "auto", backend = "cpu", tonemap = "auto";
};

Status readRenderText(const RenderText& t, LensJobOptions& o) {
    if (t.light == "all") {
        o.lightMode = LensLightMode::All;
    } else if (t.light != "auto") {
        const auto p = parsePoint(t.light);
        if (!p)
            return invalidInput("--light: expected X,Y in pixels, auto or all, got '" + t.light +
                                "'");
        o.lightMode = LensLightMode::At;
        o.light = *p;
    }
    o.tonemap = toneOperatorNamed(t.tonemap);
    if (t.backend == "gl") {
#if FLAREKIT_HAS_GL
        o.backend = gl::glLensBackend();
#else
        return builtWithoutGl("lens render --backend gl");
#endif
    }
    return Ok{};
}

int runRender(const RenderText& text, LensJobOptions options) {
    if (Status s = readRenderText(text, options); !s) return report(s.error());
    options.encode = encodeSettings();
    CliRun run("lens render");
    return run.finish(runLensJob(options, run.events()));
}

}  // namespace

void addLensRenderCommand(CLI::App* lens, int& exitCode) {
    CLI::App* render = lens->add_subcommand("render", "the lens's flare on an image");
    auto job = std::make_shared<LensJobOptions>();
    auto text = std::make_shared<RenderText>();
    addLensChoiceOptions(render, *job);
    render
        ->add_option("input", job->input,
                     "input image (EXR kept linear; 8-bit files sRGB), or a frame pattern "
                     "(shot.####.exr) for a sequence")
        ->required();
    render->add_option("-o,--output", job->output, "output image")->required();
    render
        ->add_option("--light", text->light,
                     "X,Y in pixels, auto (the brightest region) or all (every bright area "
                     "is a source, merged on a grid)")
        ->capture_default_str();
    addParamOptions<LensJobOptions>(render, std::span(kLensJobParams).subspan(1), *job);
    render->add_option("--layers", job->layersDir,
                       "also write ghosts, starburst, glare and flare (their sum) as linear EXR "
                       "into DIR");
    render
        ->add_option("--backend", text->backend,
                     "cpu, or gl: the ghost meshes rasterised by OpenGL 4.5 (headless EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    render
        ->add_option("--tonemap", text->tonemap,
                     "display curve for 8/16-bit outputs: auto (filmic for HDR input), none, "
                     "aces, filmic")
        ->check(CLI::IsMember(toneChoices({"auto"})))
        ->capture_default_str();
    render->add_option("--dirt-file", job->dirtFile,
                       "the iris plane's transmission from an image (your dust, scratches or "
                       "aperture shape): luminance 1 clear, 0 opaque, stretched over the stop; "
                       "it shapes the starburst");
    render->add_flag("-v,--verbose", job->verbose,
                     "--backend gl: print the GPU and read-back times");
    addParamOptions<LensRenderOptions>(render, kLensRenderParams, job->render);
    addParamChoice<LensRenderOptions>(render, kLensRenderParams, "ghost_level", job->render);
    addPartOption(render, job->part);
    addLayersInOutputOption(render, job->layersInOutput);
    addShotOptions(render, job->shot);
    render->callback([job, text, &exitCode] { exitCode = runRender(*text, *job); });
}

}  // namespace flarekit::cli
