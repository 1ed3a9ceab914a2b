// flarekit render: the scene through the headless GL renderer, with the sprite flare at the
// sun scaled by its coverage. With `raycast` the flare is drawn on the CPU over the read-back
// frame; with a GPU method the flare is drawn on the GPU and reads the method's 1x1 coverage
// texture in its vertex shader (the coverage is read back only for --verbose).
#include <cstdio>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/GpuFlare.h"
#include "flarekit/GpuVisibility.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Render.h"
#include "flarekit/Tonemap.h"
#include "gl/HeadlessGl.h"

namespace flarekit::cli {

namespace {
struct RenderArgs {
    std::string scene, out, preset = "tanczos-classic", method = "raycast", variant = "circle";
    ToneParams tone;  //!< only the exposure: 8/16-bit outputs get the ACES fit
    RenderOptions render;
    bool noFlare = false, noShadows = false, verbose = false;
};

struct RenderedFrame {
    Image image;
    FlaredFrame flare;
    double coverage = 0, inFrame = 0;
};

Result<RenderedFrame> renderWithRaycast(const Scene& scene, const Preset& preset, const RenderOptions& options, bool flare) {
    auto frame = renderScene(scene, options);
    if (!frame) return frame.error();
    auto visibility = raycastVisibility(scene);
    if (!visibility) return visibility.error();
    RenderedFrame r{std::move(*frame), {}, visibility->coverage, visibility->inFrame};
    r.flare = flare ? addSunFlare(r.image, scene, preset, visibility->coverage) : FlaredFrame{};
    return r;
}

Result<RenderedFrame> renderWithGpuMethod(const Scene& scene, const Preset& preset, const RenderOptions& options,
                                          const RenderArgs& a) {
    auto renderer = SceneRenderer::create(scene, options);
    if (!renderer) return renderer.error();
    GpuVisibilityOptions methodOptions;
    methodOptions.textureMaskVariant = a.variant;
    auto method = createGpuVisibility(a.method, scene, methodOptions);
    if (!method) return method.error();
    // A still frame: late methods (pbo, query) need the frame drawn until their result is in.
    auto coverage = measureStillFrame(**method, *renderer, scene);
    if (!coverage) return coverage.error();
    RenderedFrame r{{}, {}, *coverage, sunInFrameFraction(scene)};
    if (!a.noFlare) {
        auto flare = GpuSpriteFlare::create(preset, scene.height);
        if (!flare) return flare.error();
        auto drawn = flare->draw(*renderer, scene, (*method)->coverageTexture(), 0);
        if (!drawn) return drawn.error();
        r.flare = *drawn;
        r.flare.flareIntensity *= float(*coverage);  // for the report; the GPU read it itself
    }
    auto image = renderer->readColor();
    if (!image) return image.error();
    r.image = std::move(*image);
    return r;
}

int runRender(const RenderArgs& a) {
    if (Status s = checkOutputPath(a.out); !s) return report(s.error());
    const bool onGpu = isGpuVisibilityMethod(a.method);
    if (a.method != "raycast" && !onGpu) {
        return report(invalidInput("--method: expected one of " + visibilityMethodList() + ", got '" + a.method + "'"));
    }
    auto scene = loadScene(a.scene);
    if (!scene) return report(scene.error());
    auto preset = loadPreset(a.preset);
    if (!preset) return report(preset.error());
    auto gl = gl::HeadlessGl::create();
    if (!gl) return report(gl.error());
    RenderOptions options = a.render;
    options.shadows = !a.noShadows;
    auto frame = onGpu ? renderWithGpuMethod(*scene, *preset, options, a)
                       : renderWithRaycast(*scene, *preset, options, !a.noFlare);
    if (!frame) return report(frame.error());
    if (a.verbose) {
        const FlaredFrame& flare = frame->flare;
        std::printf("%s via %s; coverage %.4f (%s), in frame %.3f; sun at %.1f,%.1f%s; flare intensity %.3f\n",
                    (*gl)->renderer().c_str(), (*gl)->platform().c_str(), frame->coverage, a.method.c_str(),
                    frame->inFrame, double(flare.sunPixel.x), double(flare.sunPixel.y),
                    flare.sunInFront ? "" : " (behind the camera)", double(flare.flareIntensity));
    }
    if (!isFloatFormat(outputSampleFormat(a.out))) tonemapAcesFitted(frame->image, a.tone.exposure);
    if (Status s = writeImage(a.out, frame->image); !s) return report(s.error());
    return kExitOk;
}
}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene (headless OpenGL) with a sun flare scaled by its visibility");
    cmd->add_option("scene", args->scene, "scene JSON (see architecture.md)")->required();
    cmd->add_option("-o,--output", args->out, "output image: EXR stays linear HDR, 8/16-bit outputs are tone-mapped")
        ->required();
    cmd->add_option("--preset", args->preset, "sprite flare preset (name or JSON file)")->capture_default_str();
    cmd->add_option("--method", args->method,
                    "visibility method, one of " + visibilityMethodList() +
                        " (raycast: flare drawn on the CPU; the others: the flare reads its coverage on the GPU)")
        ->capture_default_str();
    cmd->add_option("--variant", args->variant, "texture-mask sampling: square (16x16, 256 points), circle, bilinear")
        ->check(CLI::IsMember({"square", "circle", "bilinear"}))
        ->capture_default_str();
    addParamOption<ToneParams>(cmd, kToneParams, "exposure", args->tone);
    addParamOptions<RenderOptions>(cmd, kRenderParams, args->render);
    cmd->add_flag("--no-shadows", args->noShadows, "light every surface (no sun shadow map)");
    cmd->add_flag("--no-flare", args->noFlare, "the frame only");
    cmd->add_flag("-v,--verbose", args->verbose, "print the renderer, coverage and sun position");
    cmd->callback([args, &exitCode] { exitCode = runRender(*args); });
}

}  // namespace flarekit::cli
