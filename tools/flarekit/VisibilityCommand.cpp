// SPDX-License-Identifier: Apache-2.0
// flarekit visibility: how much of the sun a scene's camera sees, by the CPU ground truth
// (`raycast`) or any GPU method of the seed articles on the headless GL backend.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "Common.h"
#include "EngineRun.h"
#include "JsonLine.h"
#include "ParamOptions.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/Render.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/GpuVisibility.h"
#include "flarekit/gl/HeadlessGl.h"
#endif

namespace flarekit::cli {

namespace {
struct VisibilityArgs {
    std::string scene, method = "raycast", variant = "circle", backend = "gl";
    RaycastOptions raycast;
    RenderOptions render;
    bool json = false;
};

#if FLAREKIT_HAS_GL
Result<VisibilityResult> runGpu(const VisibilityArgs& a, const Scene& scene, int& latency) {
    SceneVisibilityOptions o;
    o.source = a.scene;
    o.method = a.method;
    o.methodOptions.textureMaskVariant = a.variant;
    o.render = a.render;
    o.backend = a.backend;
    return gpuSceneVisibility(scene, o, &latency);
}
#else
Result<VisibilityResult> runGpu(const VisibilityArgs& a, const Scene&, int&) {
    return builtWithoutGl("visibility --method " + a.method);
}
#endif

int runVisibility(const VisibilityArgs& a) {
    auto scene = loadScene(a.scene);
    if (!scene) return report(scene.error());
    int latency = 0;
    Result<VisibilityResult> r = internalError("unreached");
    if (a.method == "raycast") {
        if (a.backend != "gl")
            return report(invalidInput("--backend " + a.backend +
                                       ": expected --method compute (raycast runs on the CPU)"));
        r = raycastVisibility(*scene, a.raycast);
    } else {
        r = runGpu(a, *scene, latency);
    }
    if (!r) return report(r.error());
    if (a.json) {
        JsonLine j;
        j.text("method", r->method)
            .number("coverage", r->coverage, 6)
            .number("in_frame", r->inFrame, 6);
        j.integer("samples", (long long)r->samples)
            .integer("latency_frames", latency)
            .number("cpu_ms", r->milliseconds, 3);
        j.json("lights", lightsJson(r->lights));
        std::printf("%s\n", j.str().c_str());
    } else {
        std::printf("%s: coverage %.4f (%.1f%% of the sun visible), %.1f%% of the disc in frame",
                    r->method.c_str(), r->coverage, 100 * r->coverage, 100 * r->inFrame);
        if (r->samples) std::printf(", %zu rays", r->samples);
        if (latency) std::printf(", result %d frame%s late", latency, latency > 1 ? "s" : "");
        std::printf(", %.1f ms\n", r->milliseconds);
        if (r->lights.size() > 1) printLights(r->lights);
    }
    return kExitOk;
}
}  // namespace

void addVisibilityCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<VisibilityArgs>();
    CLI::App* cmd = app.add_subcommand("visibility",
                                       "Fraction of the sun's disc visible from a scene's camera");
    cmd->add_option("scene", args->scene, "scene JSON (docs/scenes.md)")->required();
    std::vector<std::string> methods = {"raycast"};
    for (const std::string& m : gpuVisibilityMethods()) methods.push_back(m);
    cmd->add_option("--method", args->method,
                    "one of " + visibilityMethodList() +
                        " (raycast: the CPU ground truth; the others run on the GPU)")
        ->check(CLI::IsMember(methods))
        ->capture_default_str();
    cmd->add_option(
           "--variant", args->variant,
           "texture-mask sampling: square (16x16, 256 points), circle, bilinear (64 points)")
        ->check(CLI::IsMember(choiceNames(kTextureMaskVariantNames)))
        ->capture_default_str();
    cmd->add_option("--backend", args->backend,
                    "the engine API's backend for --method compute: gl or vulkan (needs a "
                    "Vulkan 1.3 driver)")
        ->check(CLI::IsMember({"gl", "vulkan"}))
        ->capture_default_str();
    addParamOptions<RaycastOptions>(cmd, kRaycastParams, args->raycast);
    addParamOptions<RenderOptions>(cmd, kRenderParams, args->render);
    cmd->add_flag(
        "--json", args->json,
        "print one JSON object: method, coverage, in_frame, samples, latency_frames, cpu_ms");
    cmd->callback([args, &exitCode] { exitCode = runVisibility(*args); });
}

}  // namespace flarekit::cli
