// SPDX-License-Identifier: Apache-2.0
// GL scene render time per frame on the demo world (headless EGL; llvmpipe here, the GPU where
// one is lent): GPU ms of the draw from a timer query, wall ms of the draw alone (glFinish)
// and with the float read-back, with and without the sun's shadow map; and a whole demo frame
// (draw, read-back, raycast, flare, tone map) at 720p.
#include <benchmark/benchmark.h>

#include <epoxy/gl.h>

#include <epoxy/gl.h>
#include "flarekit/Demo.h"
#include "flarekit/gl/DemoAnimation.h"
#include "flarekit/gl/Render.h"

#include "flarekit/gl/GpuTimer.h"
#include "flarekit/gl/HeadlessGl.h"

using namespace flarekit;

namespace {

gl::HeadlessGl* context(benchmark::State& state) {
    static auto gl = gl::HeadlessGl::create();
    if (!gl) {
        state.SkipWithError(gl.error().message.c_str());
        return nullptr;
    }
    return gl->get();
}

//! args: width, height, shadows (0/1), read back (0/1)
void BM_RenderDemoScene(benchmark::State& state) {
    gl::HeadlessGl* gl = context(state);
    if (!gl) return;
    const int w = int(state.range(0)), h = int(state.range(1));
    RenderOptions options;
    options.shadows = state.range(2) != 0;
    const bool readBack = state.range(3) != 0;
    auto renderer = SceneRenderer::create(demoScene(w, h, 0), options);
    if (!renderer) {
        state.SkipWithError(renderer.error().message.c_str());
        return;
    }
    std::vector<Scene> views;  // cameras along the drive; draw() reads no objects from them
    for (int i = 0; i < 64; ++i) {
        Scene v = demoScene(w, h, i / 64.0);
        v.spheres.clear(), v.boxes.clear(), v.triangles.clear();
        views.push_back(std::move(v));
    }
    GpuTimer timer;
    double gpuMs = 0;
    std::size_t frame = 0;
    for (auto _ : state) {
        timer.begin();
        (void)renderer->draw(views[frame++ % views.size()]);
        timer.end();
        if (readBack) {
            auto image = renderer->readColor();
            benchmark::DoNotOptimize(image);
        } else {
            glFinish();
        }
        gpuMs += timer.milliseconds();
    }
    state.counters["gpu_ms"] = gpuMs / double(state.iterations());
    state.counters["Mpx/s"] =
        benchmark::Counter(double(w) * h * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.SetLabel(gl->renderer());
}
BENCHMARK(BM_RenderDemoScene)
    ->ArgNames({"w", "h", "shadows", "readback"})
    ->Args({1280, 720, 1, 0})
    ->Args({1280, 720, 0, 0})
    ->Args({1280, 720, 1, 1})
    ->Args({3840, 2160, 1, 0})
    ->Args({3840, 2160, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_DemoFrame720p(benchmark::State& state) {
    gl::HeadlessGl* gl = context(state);
    if (!gl) return;
    auto preset = loadPreset("tanczos-classic");
    DemoSettings settings;
    settings.frames = 100000;
    auto demo = DemoAnimation::create(settings, *preset);
    if (!demo) {
        state.SkipWithError(demo.error().message.c_str());
        return;
    }
    for (auto _ : state) {
        auto frame = demo->next();
        benchmark::DoNotOptimize(frame);
    }
    state.SetLabel(gl->renderer());
}
BENCHMARK(BM_DemoFrame720p)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
