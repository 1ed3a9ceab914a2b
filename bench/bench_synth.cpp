// SPDX-License-Identifier: Apache-2.0
// The flare-data generator's rates (samples/s) at 512x512: in memory for each flare kind (one
// light, no camera model), with 4 lights, with the camera model; and with the files written in
// each layout (one sample per iteration, through runSynthJob's writer, on all cores). And the
// C++ side of the Python module's smallest call: postFxPixels on a 64x64 image, which
// bench/python/call_overhead.py times through `flarekit.postfx`.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "flarekit/Synth.h"
#include "flarekit/job/PixelJob.h"

using namespace flarekit;

namespace {

SynthConfig kind(double sprite, double postfx, double lens) {
    SynthConfig c;
    c.spriteWeight = sprite, c.postfxWeight = postfx, c.lensWeight = lens;
    c.lightsMin = c.lightsMax = 1;
    return c;
}

void samplesPerSecond(benchmark::State& state, double perIteration) {
    state.counters["samples/s"] =
        benchmark::Counter(perIteration, benchmark::Counter::kIsIterationInvariantRate);
}

void inMemory(benchmark::State& state, const SynthConfig& config) {
    std::uint64_t index = 0;
    for (auto _ : state) {
        auto sample = synthSample(index++, 1, 512, 512, config);
        if (!sample) state.SkipWithError(sample.error().message.c_str());
        benchmark::DoNotOptimize(sample);
    }
    samplesPerSecond(state, 1);
}

void BM_SampleSprite(benchmark::State& state) {
    inMemory(state, kind(1, 0, 0));
}
void BM_SamplePostFx(benchmark::State& state) {
    inMemory(state, kind(0, 1, 0));
}
void BM_SampleLens(benchmark::State& state) {
    inMemory(state, kind(0, 0, 1));
}
void BM_SampleSprite4Lights(benchmark::State& state) {
    SynthConfig c = kind(1, 0, 0);
    c.lightsMin = c.lightsMax = 4;
    inMemory(state, c);
}
void BM_SampleSpriteCamera(benchmark::State& state) {
    SynthConfig c = kind(1, 0, 0);
    c.camera = true;
    inMemory(state, c);
}

//! A set of 8 samples written per iteration (the default mix of kinds), samples in parallel.
void written(benchmark::State& state, SynthFormat format, int depth) {
    const std::string out =
        (std::filesystem::temp_directory_path() / "flarekit-bench-synth").string();
    std::uint64_t seed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        std::filesystem::remove_all(out);
        state.ResumeTiming();
        SynthRunOptions o;
        o.count = 8, o.seed = ++seed, o.out = out, o.format = format, o.depth = depth;
        o.config = kind(1, 1, 0);
        auto report = runSynthJob(o);
        if (!report) state.SkipWithError(report.error().message.c_str());
    }
    std::filesystem::remove_all(out);
    samplesPerSecond(state, 8);
}
void BM_WritePairs8(benchmark::State& state) {
    written(state, SynthFormat::Pairs, 8);
}
void BM_WritePairs16(benchmark::State& state) {
    written(state, SynthFormat::Pairs, 16);
}
void BM_WriteExr(benchmark::State& state) {
    written(state, SynthFormat::Exr, 8);
}
void BM_WriteFlare7kpp(benchmark::State& state) {
    written(state, SynthFormat::Flare7kpp, 8);
}

//! The in-memory postfx job on 64x64 (the input copied in each time, as the module copies it).
void BM_PostFxPixels64(benchmark::State& state) {
    Image image(64, 64);
    image.fill({0.2f, 0.2f, 0.2f, 1.f});
    image.at(20, 30) = {500.f, 500.f, 500.f, 1.f};
    PostFxJobOptions options;
    for (auto _ : state) {
        PixelInput input;
        input.image = image;
        auto out = postFxPixels(options, std::move(input));
        if (!out) state.SkipWithError(out.error().message.c_str());
        benchmark::DoNotOptimize(out);
    }
}

}  // namespace

BENCHMARK(BM_PostFxPixels64)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_SampleSprite)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SamplePostFx)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SampleLens)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(4);
BENCHMARK(BM_SampleSprite4Lights)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SampleSpriteCamera)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WritePairs8)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_WritePairs16)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_WriteExr)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_WriteFlare7kpp)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_MAIN();
