// SPDX-License-Identifier: Apache-2.0
// flarekit lights: a scene with many lights rendered through the engine API (flarekit.h), the
// way an application embeds it: the renderer's depth goes to fk_engine_occlusion (every
// light in one batched pass), and fk_engine_draw adds every light's flare to the HDR frame.
#include <cstdio>

#include "Common.h"
#include "EngineRun.h"
#include "JsonLine.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Tonemap.h"

namespace flarekit::cli {

namespace {
struct LightsArgs {
    std::string scene, out, method = "compute", tonemap = "aces", backend = "gl";
    ToneParams tone;
    RenderOptions render;
    EngineMeasureSettings measure;
    bool noShadows = false, json = false, verbose = false;
};

void printReport(const LightsArgs& a, const EngineRun& run) {
    if (a.json) {
        JsonLine j;
        j.text("method", a.method).integer("lights", (long long)run.lights.size());
        j.number("cpu_ms", run.cpuMs, 3)
            .number("occlusion_gpu_ms", run.occlusionGpuMs, 3)
            .number("draw_gpu_ms", run.drawGpuMs, 3);
        j.json("lights_coverage", lightsJson(run.lights));
        std::printf("%s\n", j.str().c_str());
        return;
    }
    int seen = 0;
    for (const LightVisibility& l : run.lights) seen += l.coverage > 0 ? 1 : 0;
    std::printf(
        "%s: %zu lights, %d at least partly visible; %.3f ms CPU in the API calls, GPU "
        "%.3f ms occlusion + %.3f ms flares (%s)\n",
        a.out.c_str(), run.lights.size(), seen, run.cpuMs, run.occlusionGpuMs, run.drawGpuMs,
        run.renderer.c_str());
    if (a.verbose) printLights(run.lights);
}

int runLights(const LightsArgs& a) {
    return runImageJob(a.out, [&]() -> Result<ImageOutput> {
        auto scene = loadScene(a.scene);
        if (!scene) return scene.error();
        EngineRunOptions o;
        o.source = a.scene;
        o.method = a.method;
        o.render = a.render;
        o.render.shadows = !a.noShadows;
        o.measure = a.measure;
        o.backend = a.backend;
        auto run = runEngine(*scene, o);
        if (!run) return run.error();
        printReport(a, *run);
        toneMapImage(run->image, renderedFrameCurve(a.out, a.tonemap), a.tone.exposure);
        return ImageOutput{std::move(run->image), {}};
    });
}
}  // namespace

void addLightsCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<LightsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "lights",
        "Render a scene with many lights through the engine API: every light measured on the "
        "frame's depth in one pass, every flare drawn instanced");
    cmd->add_option("scene", args->scene, "scene JSON with a \"lights\" array (docs/scenes.md)")
        ->required();
    cmd->add_option("-o,--output", args->out,
                    "output image: EXR stays linear HDR, 8/16-bit outputs are tone-mapped")
        ->required();
    cmd->add_option("--method", args->method,
                    "visibility method of the engine API: compute (the frame's depth, one "
                    "batched GPU pass) or texture-mask (a sun map per light: off-screen lights "
                    "and translucency exact)")
        ->check(CLI::IsMember(choiceNames(kEngineMethodNames)))
        ->capture_default_str();
    addParamOptions<RenderOptions>(cmd, kRenderParams, args->render);
    cmd->add_option("--backend", args->backend,
                    "the engine API's backend: gl, or vulkan (the scene's depth drawn again by a "
                    "Vulkan device; needs a Vulkan 1.3 driver)")
        ->check(CLI::IsMember({"gl", "vulkan"}))
        ->capture_default_str();
    addParamOption<EngineMeasureSettings>(cmd, kEngineMeasureParams, "samples", args->measure);
    addParamOption<EngineMeasureSettings>(cmd, kEngineMeasureParams, "tile-below", args->measure);
    addParamOption<ToneParams>(cmd, kToneParams, "exposure", args->tone);
    cmd->add_option("--tonemap", args->tonemap,
                    "display curve of 8/16-bit outputs: aces, filmic, none; EXR stays linear")
        ->check(CLI::IsMember(toneChoices({})))
        ->capture_default_str();
    cmd->add_flag("--no-shadows", args->noShadows, "light every surface (no sun shadow map)");
    cmd->add_flag("--json", args->json,
                  "print one JSON object: method, lights, cpu_ms, occlusion_gpu_ms, draw_gpu_ms, "
                  "lights_coverage [{coverage, in_frame}, ...]");
    cmd->add_flag("-v,--verbose", args->verbose, "print every light's coverage");
    cmd->callback([args, &exitCode] { exitCode = runLights(*args); });
}

}  // namespace flarekit::cli
