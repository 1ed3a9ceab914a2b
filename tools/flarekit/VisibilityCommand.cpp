// flarekit visibility: how much of the sun a scene's camera sees. Only the CPU ground truth
// `raycast` exists so far; the GPU methods of the contract arrive with the GL backend.
#include <cstdio>

#include "Common.h"
#include "flarekit/Visibility.h"

namespace flarekit::cli {

namespace {
struct VisibilityArgs {
    std::string scene, method = "raycast";
    int samplesPerSide = RaycastOptions{}.samplesPerSide;
    bool json = false;
};

int runVisibility(const VisibilityArgs& a) {
    if (a.method != "raycast") {
        return report(invalidInput("--method: '" + a.method +
                                   "' needs the OpenGL backend, which is not built yet; available: raycast"));
    }
    auto scene = loadScene(a.scene);
    if (!scene) return report(scene.error());
    RaycastOptions options;
    options.samplesPerSide = a.samplesPerSide;
    auto r = raycastVisibility(*scene, options);
    if (!r) return report(r.error());
    if (a.json) {
        std::printf("{\"method\": \"%s\", \"coverage\": %.6f, \"in_frame\": %.6f, \"samples\": %zu, \"cpu_ms\": %.3f}\n",
                    r->method.c_str(), r->coverage, r->inFrame, r->samples, r->milliseconds);
    } else {
        std::printf("%s: coverage %.4f (%.1f%% of the sun visible), %.1f%% of the disc in frame, %zu rays, %.1f ms\n",
                    r->method.c_str(), r->coverage, 100 * r->coverage, 100 * r->inFrame, r->samples, r->milliseconds);
    }
    return kExitOk;
}
}  // namespace

void addVisibilityCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<VisibilityArgs>();
    CLI::App* cmd = app.add_subcommand("visibility", "Fraction of the sun's disc visible from a scene's camera");
    cmd->add_option("scene", args->scene, "scene JSON (see architecture.md)")->required();
    cmd->add_option("--method", args->method,
                    "raycast (CPU ground truth); readback pbo query texture-mask texture-mask-screen burnout "
                    "compute need the GL backend")
        ->check(CLI::IsMember({"raycast", "readback", "pbo", "query", "texture-mask", "texture-mask-screen", "burnout",
                               "compute"}))
        ->capture_default_str();
    cmd->add_option("--samples", args->samplesPerSide, "raycast: strata per side (N^2 rays)")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    cmd->add_flag("--json", args->json, "print one JSON object: method, coverage, in_frame, samples, cpu_ms");
    cmd->callback([args, &exitCode] { exitCode = runVisibility(*args); });
}

}  // namespace flarekit::cli
