// GL scene render time per frame (headless EGL; llvmpipe here, the GPU where one is lent):
// wall ms of renderScene (draw + read-back) and GPU ms of the draw from a timer query.
#include <benchmark/benchmark.h>

#include <epoxy/gl.h>

#include "flarekit/Render.h"
#include "gl/GlObjects.h"
#include "gl/HeadlessGl.h"

using namespace flarekit;

namespace {

Scene benchScene(int w, int h) {
    Scene s;
    s.width = w;
    s.height = h;
    s.camera.position = {0, 1.7, 0};
    s.camera.lookAt = {0, 5, -20};
    s.sun.direction = normalize(Vec3{0.2, 0.3, -1});
    for (int i = 0; i < 40; ++i) s.spheres.push_back({{-10.0 + i * 0.5, 3.0 + (i % 5), -20.0 - i}, 1.2, {0.2, 0.5, 0.1}});
    for (int i = 0; i < 10; ++i) s.boxes.push_back({{-20.0 + 4 * i, 0, -60}, {-18.0 + 4 * i, 6.0 + i, -55}, {0.4, 0.4, 0.4}});
    return s;
}

void BM_RenderScene(benchmark::State& state) {
    static auto gl = gl::HeadlessGl::create();
    if (!gl) {
        state.SkipWithError(gl.error().message.c_str());
        return;
    }
    const Scene s = benchScene(int(state.range(0)), int(state.range(1)));
    gl::TimerQuery timer;
    double gpuMs = 0;
    for (auto _ : state) {
        timer.begin();
        auto frame = renderScene(s);
        timer.end();
        gpuMs += timer.milliseconds();
        benchmark::DoNotOptimize(frame);
    }
    state.counters["gpu_ms"] = gpuMs / double(state.iterations());
    state.SetLabel((*gl)->renderer());
}
BENCHMARK(BM_RenderScene)->Args({1280, 720})->Args({3840, 2160})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
