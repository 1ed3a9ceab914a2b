// SPDX-License-Identifier: Apache-2.0
// A scene's lights measured by a GPU method (flarekit/gl/GpuVisibility.h): `flarekit
// visibility --method ...` and any front end that reports what a method sees.
#include <algorithm>
#include <chrono>
#include <utility>

#include "flarekit/gl/EngineRun.h"
#include "flarekit/gl/GpuVisibility.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit {

namespace {
using Clock = std::chrono::steady_clock;

//! The first light's numbers as the result's own, and the time since `start`.
VisibilityResult finished(VisibilityResult r, Clock::time_point start) {
    r.coverage = r.lights.front().coverage;
    r.inFrame = r.lights.front().inFrame;
    r.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return r;
}

//! Every light at once through the engine API's batched pass (`compute` on a scene with
//! more than the sun): the coverage the embedding API would give an application.
Result<VisibilityResult> engineLightsVisibility(const Scene& scene,
                                                const SceneVisibilityOptions& a) {
    EngineRunOptions o;
    o.source = a.source;
    o.method = a.method;
    o.render = a.render;
    o.render.shadows = false;
    o.flares = false;
    o.backend = a.backend;
    const auto start = Clock::now();
    auto run = runEngineScene(scene, o);
    if (!run) return run.error();
    VisibilityResult r;
    r.method = a.method;
    r.lights = run->lights;
    return finished(std::move(r), start);
}

}  // namespace

Result<VisibilityResult> gpuSceneVisibility(const Scene& scene, const SceneVisibilityOptions& a,
                                            int* latencyFrames) {
    int latency = 0;
    const std::vector<SceneLight> lights = sceneLights(scene);
    if (a.backend == "vulkan") {
        if (a.method != "compute") {
            return invalidInput(
                "--backend vulkan: expected --method compute (the Vulkan "
                "backend's batched pass), got " +
                a.method);
        }
        return engineLightsVisibility(scene, a);
    }
    if ((a.method == "compute" || a.method == "texture-mask") &&
        (lights.size() > 1 || lights.front().type != LightType::Directional))
        return engineLightsVisibility(scene, a);
    auto context = gl::createFrameContext(scene.width, scene.height, a.render.msaaSamples,
                                          a.source + ": image");
    if (!context) return context.error();
    RenderOptions render = a.render;
    render.shadows = false;  // visibility reads depth only
    auto renderer = SceneRenderer::create(scene, render);
    if (!renderer) return renderer.error();
    auto method = createGpuVisibility(a.method, scene, a.methodOptions);
    if (!method) return method.error();
    const auto start = Clock::now();
    VisibilityResult r;
    r.method = a.method;
    for (const SceneLight& light : lights) {
        Scene view = scene;
        view.sun = lightAsSun(light, scene.camera);
        int frames = 0;
        auto coverage = measureStillFrame(**method, *renderer, view, 16, &frames);
        if (!coverage) return coverage.error();
        latency = std::max(latency, frames);
        r.lights.push_back({*coverage, lightInFrameFraction(scene, light)});
    }
    if (latencyFrames) *latencyFrames = latency;
    return finished(std::move(r), start);
}

}  // namespace flarekit
