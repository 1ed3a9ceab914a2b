// SPDX-License-Identifier: Apache-2.0
// The PSP GE emulator running the Burnout and Ridge Racer frames: frames/s and the
// GE's pixel rate, correct and naive memory models, on a half-occluded sun with a tree-line of
// occluders (about 40,000 occluder pixels drawn as row sprites).
#include <benchmark/benchmark.h>

#include "flarekit/Psp.h"

using namespace flarekit::psp;

namespace {
PspFrameInput benchInput(bool naive) {
    PspFrameInput in;
    in.occluders.assign(std::size_t(kScreenWidth * kScreenHeight), 0);
    for (int y = 0; y < kScreenHeight; ++y)
        for (int x = 0; x < kScreenWidth; ++x)
            if (y > 180 - (x * 37 % 23) || (x >= 236 && x < 240))
                in.occluders[std::size_t(y * kScreenWidth + x)] = 1;
    in.sunX = 240, in.sunY = 100;
    in.naive = naive;
    return in;
}

void BM_PspFrame(benchmark::State& state, PspTrick trick, bool naive) {
    const PspFrameInput in = benchInput(naive);
    int coverage = 0;
    for (auto _ : state) {
        auto r = runPspFrame(trick, in);
        if (!r) {
            state.SkipWithError(r.error().message.c_str());
            return;
        }
        coverage = r->coverageByte;
        benchmark::DoNotOptimize(r->frame.pixels.data());
    }
    state.counters["fps"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["screen_Mpx_per_s"] =
        benchmark::Counter(double(state.iterations()) * kScreenWidth * kScreenHeight / 1e6,
                           benchmark::Counter::kIsRate);
    state.counters["coverage_byte"] = coverage;
}
}  // namespace

BENCHMARK_CAPTURE(BM_PspFrame, burnout, PspTrick::Burnout, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PspFrame, burnout_naive, PspTrick::Burnout, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PspFrame, ridge_racer, PspTrick::RidgeRacer, false)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
