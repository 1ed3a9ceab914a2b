// SPDX-License-Identifier: Apache-2.0
// Seed-002 blending throughput. Megapixels/s per mode; for the saturating add, the three
// implementations against memcpy over the same buffers in the same run (the SIMD add
// >= 70% of memcpy's GB/s). bytes_per_second counts the buffer size once for every kernel
// (the add reads two buffers and writes one: 1.5x memcpy's memory traffic).
#include <benchmark/benchmark.h>

#include <cstring>
#include <random>
#include <vector>

#include "flarekit/Blend.h"

using namespace flarekit;

namespace {

std::vector<std::uint8_t> randomBytes(std::size_t n, unsigned seed) {
    std::vector<std::uint8_t> v(n);
    std::mt19937 rng(seed);
    for (auto& b : v) b = std::uint8_t(rng());
    return v;
}

void setRates(benchmark::State& state, std::size_t bytes, std::size_t pixels) {
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes));
    state.counters["MP/s"] =
        benchmark::Counter(double(pixels) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// range(0): bytes per buffer. 1920x1080 RGBA = 8,294,400 (past L2); 256 KiB stays in cache.
void BM_Memcpy(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    auto a = randomBytes(n, 1), out = randomBytes(n, 3);
    for (auto _ : state) {
        std::memcpy(out.data(), a.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    setRates(state, n, n / 4);
}

template <void (*Add)(const std::uint8_t*, const std::uint8_t*, std::uint8_t*, std::size_t)>
void BM_Add(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    auto a = randomBytes(n, 1), b = randomBytes(n, 2), out = randomBytes(n, 3);
    for (auto _ : state) {
        Add(a.data(), b.data(), out.data(), n);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    setRates(state, n, n / 4);
    state.SetLabel(Add == &blend8::addSpanSimd ? std::string(blend8::addSimdIsa()) : "");
}

// In place, dst = min(src + dst, 255), as `flarekit blend --mode add` runs it.
template <void (*Add)(const std::uint8_t*, const std::uint8_t*, std::uint8_t*, std::size_t)>
void BM_AddInPlace(benchmark::State& state) {
    const std::size_t n = std::size_t(state.range(0));
    auto a = randomBytes(n, 1), b = randomBytes(n, 2);
    for (auto _ : state) {
        Add(a.data(), b.data(), b.data(), n);
        benchmark::DoNotOptimize(b.data());
        benchmark::ClobberMemory();
    }
    setRates(state, n, n / 4);
}

constexpr std::int64_t kFrame = 1920 * 1080 * 4;
constexpr std::int64_t kCached = 256 * 1024;
BENCHMARK(BM_Memcpy)->Arg(kFrame)->Arg(kCached);
BENCHMARK_TEMPLATE(BM_Add, blend8::addSpanScalar16)
    ->Name("BM_AddScalar16")
    ->Arg(kFrame)
    ->Arg(kCached);
BENCHMARK_TEMPLATE(BM_Add, blend8::addSpanLut)->Name("BM_AddLut")->Arg(kFrame)->Arg(kCached);
BENCHMARK_TEMPLATE(BM_Add, blend8::addSpanSimd)->Name("BM_AddSimd")->Arg(kFrame)->Arg(kCached);
BENCHMARK_TEMPLATE(BM_AddInPlace, blend8::addSpanSimd)
    ->Name("BM_AddSimdInPlace")
    ->Arg(kFrame)
    ->Arg(kCached);

// Alpha modes over a 1920x1080 frame: src RGBA, dst RGB.
template <int Mode>
void BM_AlphaMode(benchmark::State& state) {
    const std::size_t pixels = 1920 * 1080;
    auto src = randomBytes(pixels * 4, 4), dst = randomBytes(pixels * 3, 5), stored = src;
    blend8::toPremultipliedInverse(src.data(), stored.data(), pixels);
    for (auto _ : state) {
        if constexpr (Mode == 0) blend8::alphaSpan(src.data(), dst.data(), 3, pixels);
        if constexpr (Mode == 1) blend8::alphaShiftSpan(src.data(), dst.data(), 3, pixels);
        if constexpr (Mode == 2) blend8::premultipliedSpan(stored.data(), dst.data(), 3, pixels);
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
    }
    setRates(state, pixels * 3, pixels);
}
BENCHMARK_TEMPLATE(BM_AlphaMode, 0)->Name("BM_Alpha_Fig1");
BENCHMARK_TEMPLATE(BM_AlphaMode, 1)->Name("BM_AlphaShift_Fig3");
BENCHMARK_TEMPLATE(BM_AlphaMode, 2)->Name("BM_Premultiplied_Fig6");

// Float compositing (linear light, premultiplied RGBA), 1920x1080.
void BM_CompositeFloat(benchmark::State& state) {
    const std::size_t pixels = 1920 * 1080;
    std::vector<float> src(pixels * 4, 0.25f), dst(pixels * 4, 0.5f);
    const auto mode = BlendMode(state.range(0));
    for (auto _ : state) {
        compositeSpan(mode, src.data(), dst.data(), pixels);
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
    }
    setRates(state, pixels * 16, pixels);
    state.SetLabel(std::string(blendModeName(mode)));
}
BENCHMARK(BM_CompositeFloat)
    ->Arg(int(BlendMode::Add))
    ->Arg(int(BlendMode::Screen))
    ->Arg(int(BlendMode::Over));

}  // namespace

BENCHMARK_MAIN();
