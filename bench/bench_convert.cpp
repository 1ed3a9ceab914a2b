// SPDX-License-Identifier: Apache-2.0
// flarekit convert: reading each engine's fixture (examples/interop) and writing flarekit's
// shipped tanczos-classic preset to a texture-only engine (three.js: every procedural element
// baked into a PNG) and to Unity. CPU ms per file, the whole job with its file I/O.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "flarekit/Convert.h"

namespace {

const std::string kInterop = std::string(FLAREKIT_SOURCE_DIR) + "/examples/interop/";

void BM_Import(benchmark::State& state, const char* file) {
    for (auto _ : state) {
        auto asset = flarekit::importFlare(kInterop + file);
        if (!asset) state.SkipWithError(asset.error().message.c_str());
        benchmark::DoNotOptimize(asset);
    }
}
BENCHMARK_CAPTURE(BM_Import, babylon, "babylon/sun-flares.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Import, three, "three/lensflare.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Import, playcanvas, "playcanvas/look.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Import, unity, "unity/Assets/Flares/SunFlare.asset")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Import, unreal, "unreal/lensflare.ini")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Import, godot, "godot/lens_flare.tscn")->Unit(benchmark::kMillisecond);

void BM_Export(benchmark::State& state, flarekit::FlareFormat format, const char* name) {
    auto preset = flarekit::loadPreset("tanczos-classic");
    if (!preset) return state.SkipWithError(preset.error().message.c_str());
    flarekit::FlareAsset asset;
    asset.sprite = *preset;
    const auto dir = std::filesystem::temp_directory_path() / "flarekit-bench-convert";
    for (auto _ : state) {
        auto written = flarekit::exportFlare(asset, (dir / name).string(), format);
        if (!written) state.SkipWithError(written.error().message.c_str());
    }
    std::filesystem::remove_all(dir);
}
BENCHMARK_CAPTURE(BM_Export, three_baked, flarekit::FlareFormat::Three, "flare.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Export, unity, flarekit::FlareFormat::Unity, "Flare.asset")
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
