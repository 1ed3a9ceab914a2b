// SPDX-License-Identifier: Apache-2.0
// The post-process lens flare chain at 1920x1080 and 3840x2160, CPU (both cores,
// 4-wide SIMD per pixel) and OpenGL (llvmpipe here; the GPU where one is lent).
//   items/s      megapixels of input per second for the whole chain (SetItemsProcessed)
//   <pass>_ms    time of one pass per run (CPU: wall; GL: GPU timer query and wall with glFinish)
//   <pass>_MPps  megapixels that pass writes per second
// The input is the HDR sky test image (sun 50) at the benchmark's size.
#include <benchmark/benchmark.h>

#include <iterator>
#include <map>

#include "PostFxImages.h"
#include "flarekit/PostFx.h"
#include "flarekit/gl/HeadlessGl.h"

using namespace flarekit;

namespace {

const char* kPresets[] = {"killzone2", "modern", "anamorphic", "subtle", "photo"};

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

//! Runs `run(input, params, options)` per iteration after one warm-up run and reports.
//! args: preset index, width, height, timed passes (0/1: per-pass waits change the total)
template <typename Run>
void measure(benchmark::State& state, const Run& run, bool gl, const std::string& label) {
    auto params = loadPostFxPreset(kPresets[state.range(0)]);
    if (!params) return state.SkipWithError(params.error().message.c_str());
    const Image& in = input(int(state.range(1)), int(state.range(2)));
    std::vector<PassTime> times;
    PostFxOptions options;
    if (Status s = run(in, *params, options); !s)
        return state.SkipWithError(s.error().message.c_str());  // warm-up
    options.times = state.range(3) ? &times : nullptr;
    for (auto _ : state) {
        if (Status s = run(in, *params, options); !s)
            return state.SkipWithError(s.error().message.c_str());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(in.pixelCount()));
    state.SetLabel(std::string(kPresets[state.range(0)]) + label);
    report(state, times, gl);
}

void BM_PostFxCpu(benchmark::State& state) {
    CpuPostFx chain;  // buffers kept between runs, as a video or an engine would
    PostFxResult result;
    measure(
        state,
        [&](const Image& in, const PostFxParams& p, const PostFxOptions& o) {
            Status s = chain.run(in, p, result, o);
            benchmark::DoNotOptimize(result.final.data());
            return s;
        },
        false, "");
}

void BM_PostFxGl(benchmark::State& state) {
    static auto context = gl::HeadlessGl::create();
    if (!context) return state.SkipWithError(context.error().message.c_str());
    static auto chain = GpuPostFx::create();
    if (!chain) return state.SkipWithError(chain.error().message.c_str());
    measure(
        state,
        [&](const Image& in, const PostFxParams& p, const PostFxOptions& o) -> Status {
            auto r = chain->run(in, p, o);  // upload, every pass, read-back
            if (!r) return r.error();
            benchmark::DoNotOptimize(r->final.data());
            return Ok{};
        },
        true, " on " + (*context)->renderer());
}

void sizes(benchmark::internal::Benchmark* b) {
    for (int preset = 0; preset < int(std::size(kPresets)); ++preset) {
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
