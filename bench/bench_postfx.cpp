// The post-process lens flare chain (issue 6) at 1920x1080 and 3840x2160, CPU (both cores,
// 4-wide SIMD per pixel) and OpenGL (llvmpipe here; the GPU where one is lent).
//   items/s      megapixels of input per second for the whole chain (SetItemsProcessed)
//   <pass>_ms    time of one pass per run (CPU: wall; GL: GPU timer query and wall with glFinish)
//   <pass>_MPps  megapixels that pass writes per second
// The input is the HDR sky test image (sun 50) at the benchmark's size.
#include <benchmark/benchmark.h>

#include <map>

#include "PostFxImages.h"
#include "flarekit/PostFx.h"
#include "gl/HeadlessGl.h"

using namespace flarekit;

namespace {

const char* kPresets[] = {"killzone2", "modern", "anamorphic", "subtle"};

const Image& input(int w, int h) {
    static std::map<std::pair<int, int>, Image> cache;
    auto it = cache.find({w, h});
    if (it == cache.end()) it = cache.emplace(std::pair{w, h}, test::hdrSky(w, h)).first;
    return it->second;
}

void report(benchmark::State& state, const std::vector<PassTime>& times, bool gl) {
    const double runs = double(state.iterations());
    for (const PassTime& t : times) {
        const double wall = t.wallMilliseconds / runs;
        state.counters[t.pass + "_ms"] = wall;
        state.counters[t.pass + "_MPps"] = t.megapixels / runs / (wall * 1e-3);
        if (gl) state.counters[t.pass + "_gpu_ms"] = t.milliseconds / runs;
    }
}

//! args: preset index, width, height, timed passes (0/1: per-pass glFinish changes the total)
void BM_PostFxCpu(benchmark::State& state) {
    auto params = loadPostFxPreset(kPresets[state.range(0)]);
    if (!params) return state.SkipWithError(params.error().message.c_str());
    const Image& in = input(int(state.range(1)), int(state.range(2)));
    std::vector<PassTime> times;
    PostFxOptions options;
    options.times = state.range(3) ? &times : nullptr;
    CpuPostFx chain;  // buffers kept between runs, as a video or an engine would
    PostFxResult result;
    (void)chain.run(in, *params, result);  // warm-up: first-touch page faults of the buffers
    for (auto _ : state) {
        if (Status s = chain.run(in, *params, result, options); !s) return state.SkipWithError(s.error().message.c_str());
        benchmark::DoNotOptimize(result.final.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(in.pixelCount()));
    state.SetLabel(kPresets[state.range(0)]);
    report(state, times, false);
}

void BM_PostFxGl(benchmark::State& state) {
    static auto context = gl::HeadlessGl::create();
    if (!context) return state.SkipWithError(context.error().message.c_str());
    static auto chain = GpuPostFx::create();
    if (!chain) return state.SkipWithError(chain.error().message.c_str());
    auto params = loadPostFxPreset(kPresets[state.range(0)]);
    if (!params) return state.SkipWithError(params.error().message.c_str());
    const Image& in = input(int(state.range(1)), int(state.range(2)));
    std::vector<PassTime> times;
    PostFxOptions options;
    options.times = state.range(3) ? &times : nullptr;
    (void)chain->run(in, *params);  // warm-up: allocation of this size's targets
    for (auto _ : state) {
        auto r = chain->run(in, *params, options);  // upload, every pass, read-back
        benchmark::DoNotOptimize(r);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(in.pixelCount()));
    state.SetLabel(std::string(kPresets[state.range(0)]) + " on " + (*context)->renderer());
    report(state, times, true);
}

void sizes(benchmark::internal::Benchmark* b) {
    for (int preset = 0; preset < 4; ++preset) {
        for (auto [w, h] : {std::pair{1920, 1080}, std::pair{3840, 2160}}) {
            for (int timed : {0, 1}) b->Args({preset, w, h, timed});
        }
    }
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace

BENCHMARK(BM_PostFxCpu)->Apply(sizes);
BENCHMARK(BM_PostFxGl)->Apply(sizes);
BENCHMARK_MAIN();
