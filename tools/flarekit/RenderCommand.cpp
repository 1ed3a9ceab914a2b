// SPDX-License-Identifier: Apache-2.0
// flarekit render: the scene through the headless GL renderer, with the sprite flare at the
// sun scaled by its coverage. With `raycast` the flare is drawn on the CPU over the read-back
// frame; with a GPU method the flare is drawn on the GPU and reads the method's 1x1 coverage
// texture in its vertex shader (the coverage is read back only for --verbose).
#include <cstdio>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Tonemap.h"
#include "flarekit/gl/Render.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/SceneStill.h"
#endif

namespace flarekit::cli {

namespace {
struct RenderArgs {
    std::string scene, out, preset = kDefaultSpritePreset, method = "raycast", variant = "circle",
                            tonemap = "aces";
    ToneParams tone;  //!< the exposure; the curve is --tonemap (8/16-bit outputs only)
    RenderOptions render;
    bool noFlare = false, noShadows = false, verbose = false;
};

#if FLAREKIT_HAS_GL
int runRender(const RenderArgs& a) {
    return runImageJob(a.out, [&]() -> Result<ImageOutput> {
        gl::SceneStillOptions o{a.scene, a.preset, a.method, a.variant, a.render, !a.noFlare};
        o.render.shadows = !a.noShadows;
        auto still = gl::renderSceneStill(o);
        if (!still) return still.error();
        const PipelineFrame& f = still->frame;
        if (a.verbose) {
            std::printf(
                "%s via %s; coverage %.4f (%s), in frame %.3f; sun at %.1f,%.1f%s; flare "
                "intensity %.3f\n",
                still->renderer.c_str(), still->platform.c_str(), f.rawCoverage, a.method.c_str(),
                f.inFrame, double(f.sunPixel.x), double(f.sunPixel.y),
                f.sunInFront ? "" : " (behind the camera)", double(f.flareIntensity));
        }
        // The display curve for 8/16-bit files; float outputs stay linear (exposure applied).
        toneMapImage(still->frame.image, renderedFrameCurve(a.out, a.tonemap), a.tone.exposure);
        return ImageOutput{std::move(still->frame.image), {}};
    });
}
#else
int runRender(const RenderArgs&) {
    return report(builtWithoutGl("render"));
}
#endif
}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a scene (headless OpenGL) with a sun flare scaled by its visibility");
    cmd->add_option("scene", args->scene, "scene JSON (docs/scenes.md)")->required();
    cmd->add_option("-o,--output", args->out,
                    "output image: EXR stays linear HDR, 8/16-bit outputs are tone-mapped")
        ->required();
    cmd->add_option("--preset", args->preset, "sprite flare preset (name or JSON file)")
        ->capture_default_str();
    cmd->add_option("--method", args->method,
                    "visibility method, one of " + visibilityMethodList() +
                        " (raycast: flare drawn on the CPU; the others: the flare reads its "
                        "coverage on the GPU)")
        ->capture_default_str();
    cmd->add_option("--variant", args->variant,
                    "texture-mask sampling: square (16x16, 256 points), circle, bilinear")
        ->check(CLI::IsMember(choiceNames(kTextureMaskVariantNames)))
        ->capture_default_str();
    addParamOption<ToneParams>(cmd, kToneParams, "exposure", args->tone);
    cmd->add_option("--tonemap", args->tonemap,
                    "display curve of 8/16-bit outputs: aces (the demo's), filmic, none (clipped); "
                    "EXR stays linear")
        ->check(CLI::IsMember(toneChoices({})))
        ->capture_default_str();
    addParamOptions<RenderOptions>(cmd, kRenderParams, args->render);
    cmd->add_flag("--no-shadows", args->noShadows, "light every surface (no sun shadow map)");
    cmd->add_flag("--no-flare", args->noFlare, "the frame only");
    cmd->add_flag("-v,--verbose", args->verbose, "print the renderer, coverage and sun position");
    cmd->callback([args, &exitCode] { exitCode = runRender(*args); });
}

}  // namespace flarekit::cli
