// flarekit render: the scene through the headless GL renderer, with the sprite flare at the
// sun scaled by its coverage (ray-cast; the GPU methods come with the occlusion issue).
#include <cstdio>

#include "Common.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Render.h"
#include "flarekit/Tonemap.h"
#include "gl/HeadlessGl.h"

namespace flarekit::cli {

namespace {
struct RenderArgs {
    std::string scene, out, preset = "tanczos-classic", method = "raycast";
    float exposure = 1.f;
    int msaa = 1;
    bool noFlare = false, noShadows = false, verbose = false;
};

int runRender(const RenderArgs& a) {
    if (Status s = checkOutputPath(a.out); !s) return report(s.error());
    if (a.method != "raycast") {
        return report(invalidInput("--method: '" + a.method + "' is not available yet; available: raycast"));
    }
    auto scene = loadScene(a.scene);
    if (!scene) return report(scene.error());
    auto preset = loadPreset(a.preset);
    if (!preset) return report(preset.error());
    auto gl = gl::HeadlessGl::create();
    if (!gl) return report(gl.error());
    RenderOptions options;
    options.msaaSamples = a.msaa;
    options.shadows = !a.noShadows;
    auto frame = renderScene(*scene, options);
    if (!frame) return report(frame.error());
    auto visibility = raycastVisibility(*scene);
    if (!visibility) return report(visibility.error());
    const FlaredFrame flare = a.noFlare ? FlaredFrame{} : addSunFlare(*frame, *scene, *preset, visibility->coverage);
    if (a.verbose) {
        std::printf("%s via %s; coverage %.4f (%s), in frame %.3f; sun at %.1f,%.1f%s; flare intensity %.3f\n",
                    (*gl)->renderer().c_str(), (*gl)->platform().c_str(), visibility->coverage, visibility->method.c_str(),
                    visibility->inFrame, double(flare.sunPixel.x), double(flare.sunPixel.y),
                    flare.sunInFront ? "" : " (behind the camera)", double(flare.flareIntensity));
    }
    if (!isFloatFormat(outputSampleFormat(a.out))) tonemapAcesFitted(*frame, a.exposure);
    if (Status s = writeImage(a.out, *frame); !s) return report(s.error());
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
    cmd->add_option("--method", args->method, "visibility method (raycast for now)")->capture_default_str();
    cmd->add_option("--exposure", args->exposure, "exposure before tone mapping (8/16-bit outputs)")
        ->check(CLI::Range(0.f, 1000.f))
        ->capture_default_str();
    cmd->add_option("--msaa", args->msaa, "samples per pixel (1, 2, 4, 8)")
        ->check(CLI::IsMember({1, 2, 4, 8}))
        ->capture_default_str();
    cmd->add_flag("--no-shadows", args->noShadows, "light every surface (no sun shadow map)");
    cmd->add_flag("--no-flare", args->noFlare, "the frame only");
    cmd->add_flag("-v,--verbose", args->verbose, "print the renderer, coverage and sun position");
    cmd->callback([args, &exitCode] { exitCode = runRender(*args); });
}

}  // namespace flarekit::cli
