// SPDX-License-Identifier: Apache-2.0
// Sprite-flare throughput: element generation (MP/s of sprite pixels), `apply` in memory
// (light search + flare) and `apply` end to end through files, at 1920x1080 and 3840x2160,
// on 1 and 2 threads.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/Parallel.h"
#include "flarekit/Elements.h"
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;

namespace {

void megapixels(benchmark::State& state, double pixels) {
    state.counters["MP/s"] =
        benchmark::Counter(pixels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// A sky gradient with a small sun at (0.7 W, 0.3 H): what `apply --light auto` typically gets.
//! An HDR sun: 2,000 over a disc of radius 0.012 H is a flux of 0.9 H^2, near the energy
//! model's reference, so the benchmark shades the whole preset.
constexpr float kSun = 2000.f;

Image skyWithSun(int w, int h) {
    Image img(w, h);
    const float sx = 0.7f * float(w), sy = 0.3f * float(h), r = 0.012f * float(h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float v = 0.1f + 0.3f * float(y) / float(h);
            const bool sun = std::hypot(float(x) + 0.5f - sx, float(y) + 0.5f - sy) < r;
            img.at(x, y) = sun ? Rgba{kSun, kSun, kSun, 1.f} : Rgba{v, 0.6f * v, 0.9f - v, 1.f};
        }
    }
    return img;
}

// args: element type, radius in pixels
void BM_ElementGeneration(benchmark::State& state) {
    const ElementParams p = defaultElement(ElementType(state.range(0)));
    const float radius = float(state.range(1));
    std::size_t pixels = 0;
    for (auto _ : state) {
        Image sprite = renderElement(p, radius);
        pixels = sprite.pixelCount();
        benchmark::DoNotOptimize(sprite.data());
    }
    megapixels(state, double(pixels));
    state.SetLabel(std::string(elementTypeName(p.type)));
}
BENCHMARK(BM_ElementGeneration)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {256}})
    ->Unit(benchmark::kMillisecond);

// args: height (1080 or 2160), threads
void BM_ApplyInMemory(benchmark::State& state) {
    const int h = int(state.range(0)), w = h * 16 / 9;
    ThreadLimit limit(int(state.range(1)));
    const Image base = skyWithSun(w, h);
    auto preset = loadPreset("tanczos-classic");
    if (!preset) {
        state.SkipWithError(preset.error().message.c_str());
        return;
    }
    std::size_t shaded = 0;
    for (auto _ : state) {
        state.PauseTiming();
        Image img = base;
        state.ResumeTiming();
        shaded = flareLights(img, *preset, findLights(img)).pixelsShaded;
        benchmark::DoNotOptimize(img.data());
    }
    megapixels(state, double(w) * double(h));
    state.counters["shaded_MP"] = double(shaded) * 1e-6;
}
BENCHMARK(BM_ApplyInMemory)
    ->ArgsProduct({{1080, 2160}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// --light auto alone: the luminance pass, the sort of bright pixels and the candidates' flood
// fills. args: height (1080 or 2160), kind (0: the HDR sky with one sun; 1: an 8-bit-like frame
// whose upper third is clipped white, the worst case for the sort and the fills).
void BM_FindLights(benchmark::State& state) {
    const int h = int(state.range(0)), w = h * 16 / 9;
    Image img = skyWithSun(w, h);
    if (state.range(1) == 1) {
        for (int y = 0; y < h / 3; ++y)
            for (int x = 0; x < w; ++x) img.at(x, y) = {1.f, 1.f, 1.f, 1.f};
    }
    LightSearchOptions options;
    options.maxLights = 4;
    std::size_t candidates = 0;
    for (auto _ : state) {
        const LightSearch search = findLights(img, options);
        candidates = search.candidates.size();
        benchmark::DoNotOptimize(search.lights.data());
    }
    megapixels(state, double(w) * double(h));
    state.counters["candidates"] = double(candidates);
}
BENCHMARK(BM_FindLights)
    ->ArgsProduct({{1080, 2160}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// --light auto on the sample photograph (samples/sunset.png, 8-bit, 1280x720): a low sun whose
// clipped glare and bright sky give half a million seeds above the threshold, most of them
// taken by the first lights' regions and halos. arg: threads.
void BM_FindLightsSample(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    auto loaded = readImage(std::string(FLAREKIT_SAMPLES) + "/sunset.png");
    if (!loaded) {
        state.SkipWithError(loaded.error().message.c_str());
        return;
    }
    const Image& img = loaded->image;
    std::size_t candidates = 0;
    for (auto _ : state) {
        const LightSearch search = findLights(img);
        candidates = search.candidates.size();
        benchmark::DoNotOptimize(search.lights.data());
    }
    megapixels(state, double(img.pixelCount()));
    state.counters["candidates"] = double(candidates);
}
BENCHMARK(BM_FindLightsSample)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// --light X,Y on the sample photograph: the placed point's region, and the finder's pass that
// tells whether that region is one part of a larger light (a strip's spot, a window's pane).
void BM_MeasureLightAtSample(benchmark::State& state) {
    auto loaded = readImage(std::string(FLAREKIT_SAMPLES) + "/sunset.png");
    if (!loaded) {
        state.SkipWithError(loaded.error().message.c_str());
        return;
    }
    const Image& img = loaded->image;
    const Point sun = findLights(img).lights.at(0).position;
    for (auto _ : state) benchmark::DoNotOptimize(measureLightAt(img, sun).flux);
    megapixels(state, double(img.pixelCount()));
}
BENCHMARK(BM_MeasureLightAtSample)->Unit(benchmark::kMillisecond)->UseRealTime();

// The flare alone (no light search), per preset, 1080p, 2 threads: cost follows coverage.
void BM_RenderFlare(benchmark::State& state, const char* name) {
    ThreadLimit limit(2);
    Image img(1920, 1080);
    auto preset = loadPreset(name);
    if (!preset) {
        state.SkipWithError(preset.error().message.c_str());
        return;
    }
    std::size_t shaded = 0;
    for (auto _ : state) shaded = renderFlare(img, *preset, {1344.f, 324.f}, 1.f).pixelsShaded;
    state.counters["shaded_MP/s"] =
        benchmark::Counter(double(shaded) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["shaded_MP"] = double(shaded) * 1e-6;
}
BENCHMARK_CAPTURE(BM_RenderFlare, subtle, "subtle")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderFlare, tanczos_classic, "tanczos-classic")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderFlare, sun_wide, "sun-wide")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// End to end as the CLI runs it: read PNG, find the light, flare, write PNG (2 threads).
void BM_ApplyFile(benchmark::State& state) {
    const int h = int(state.range(0)), w = h * 16 / 9;
    const auto dir = std::filesystem::temp_directory_path();
    const std::string in = (dir / ("flarekit-bench-" + std::to_string(h) + ".png")).string();
    const std::string out = (dir / ("flarekit-bench-out-" + std::to_string(h) + ".png")).string();
    if (!writeImage(in, skyWithSun(w, h)).ok()) {
        state.SkipWithError("cannot write the input");
        return;
    }
    auto preset = loadPreset("tanczos-classic");
    for (auto _ : state) {
        auto loaded = readImage(in);
        flareLights(loaded->image, *preset, findLights(loaded->image));
        if (!writeImage(out, loaded->image).ok()) state.SkipWithError("write failed");
    }
    megapixels(state, double(w) * double(h));
    std::filesystem::remove(in);
    std::filesystem::remove(out);
}
BENCHMARK(BM_ApplyFile)->Arg(1080)->Arg(2160)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
