// SPDX-License-Identifier: Apache-2.0
// Lens flares from prescriptions on 2 cores: the exact ghost analysis (`lens ghosts`), and the
// CPU render of one light at 1920x1080 through the 22-surface zoom's brightest 66 ghosts (RGB
// and 16 spectral samples), `--light all` as the number of sources grows, and the starburst's
// diffraction pattern (the pupil's 2-D DFT on KissFFT, computed once per iris and cached).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "flarekit/Lens.h"
#include "lens/Fraunhofer.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/GpuLens.h"
#include "flarekit/gl/HeadlessGl.h"
#endif

using namespace flarekit;

namespace {

const Lens& zoom() {
    static const Lens lens = *loadLens("nikon-zoom-80-200");
    return lens;
}

//! Argument: GhostQuery::ghostRays (0: the 64-ray beam alone; 32768: the default refinement).
void BM_GhostAnalysis(benchmark::State& state) {
    GhostQuery q;
    q.angleXDeg = 5, q.angleYDeg = 2;
    q.ghostRays = int(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(analyseGhosts(zoom(), q).ok());
}
BENCHMARK(BM_GhostAnalysis)
    ->Arg(0)
    ->Arg(kDefaultGhostRays)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

//! The power spectrum behind one iris's PSF: an N x N disc pupil (lens render uses N = 512).
void BM_StarburstSpectrum(benchmark::State& state) {
    const int n = int(state.range(0));
    std::vector<double> pupil(std::size_t(n) * std::size_t(n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            pupil[std::size_t(y * n + x)] = std::hypot(x - n / 2 + 0.5, y - n / 2 + 0.5) < n / 8.0;
    for (auto _ : state) benchmark::DoNotOptimize(lens::centredPowerSpectrum(pupil, n).data());
    state.counters["MP/s"] = benchmark::Counter(double(n) * n * 1e-6 * double(state.iterations()),
                                                benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StarburstSpectrum)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);

//! `sources` lights spread over the upper half of a 1080p frame, each a 10^6 sun.
std::vector<LensLight> lights(int sources) {
    std::vector<LensLight> out;
    for (int i = 0; i < sources; ++i) {
        LensLight l;
        l.x = 1920 * (0.2 + 0.6 * (i + 0.5) / sources);
        l.y = 1080 * (0.2 + 0.2 * ((i * 7) % 5) / 5.0);
        l.energy = {1e6, 1e6, 1e6};
        out.push_back(l);
    }
    return out;
}

void BM_Render1080p(benchmark::State& state) {
    LensRenderOptions o;
    o.ghosts = 66;
    o.spectral = int(state.range(0));
    const auto one = lights(1);
    for (auto _ : state) benchmark::DoNotOptimize(renderLensFlare(zoom(), 1920, 1080, one, o).ok());
    state.counters["MP/s"] =
        benchmark::Counter(1920.0 * 1080 / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Render1080p)->Arg(0)->Arg(16)->Unit(benchmark::kMillisecond)->UseRealTime();

//! The starburst alone at 1080p (radius a quarter of the diagonal) at 3 wavelengths (beaded)
//! and at the default 32 (smooth): what the smooth default costs per source.
void BM_StarburstWavelengths(benchmark::State& state) {
    LensRenderOptions o;
    o.ghosts = 0, o.glare = 0;
    o.starburstSamples = int(state.range(0));
    const auto one = lights(1);
    for (auto _ : state) benchmark::DoNotOptimize(renderLensFlare(zoom(), 1920, 1080, one, o).ok());
}
BENCHMARK(BM_StarburstWavelengths)->Arg(3)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RenderSources(benchmark::State& state) {
    LensRenderOptions o;
    o.ghosts = 16;
    const auto many = lights(int(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(renderLensFlare(zoom(), 1920, 1080, many, o).ok());
}
BENCHMARK(BM_RenderSources)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

#if FLAREKIT_HAS_GL
//! The same frame with the ghosts rasterised by OpenGL; counters: GPU ms of the ghost draws
//! (timer queries) and the read-back's wall ms. `state.range(0)` x `range(1)` pixels.
void BM_RenderGl(benchmark::State& state) {
    static auto context = gl::HeadlessGl::create();
    if (!context) {
        state.SkipWithError(context.error().message.c_str());
        return;
    }
    const int w = int(state.range(0)), h = int(state.range(1));
    LensRenderOptions o;
    o.ghosts = 66;
    std::vector<LensLight> one(1);
    one[0].x = 0.7 * w, one[0].y = 0.3 * h, one[0].energy = {1e6, 1e6, 1e6};
    LensGlTimes times, sum;
    for (auto _ : state) {
        benchmark::DoNotOptimize(renderLensFlareGl(zoom(), w, h, one, o, &times).ok());
        sum.ghostsGpuMs += times.ghostsGpuMs, sum.readbackMs += times.readbackMs;
    }
    state.counters["ghosts GPU ms"] = sum.ghostsGpuMs / double(state.iterations());
    state.counters["read-back ms"] = sum.readbackMs / double(state.iterations());
}
BENCHMARK(BM_RenderGl)
    ->Args({1920, 1080})
    ->Args({10172, 5370})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
#endif

}  // namespace

BENCHMARK_MAIN();
