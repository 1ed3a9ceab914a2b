// SPDX-License-Identifier: Apache-2.0
// The studio's preview update on the CPU, as the window makes it while the light is dragged
// (the view: the image with its flare at 1280x720, the sample photograph at its own size) and
// when it stops (the component passes, each 320 pixels wide), for each shipped sprite preset.
// frames/s is what the view can follow; the window's own drawing (Dear ImGui on llvmpipe) comes on
// top, and is measured by `flarekit studio --stats` (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <string>

#include "Document.h"
#include "Preview.h"

using namespace flarekit;
using namespace flarekit::studio;

namespace {

void previewUpdate(benchmark::State& state, const std::string& preset, bool layers) {
    Document doc;
    if (Status s = doc.openImage(FLAREKIT_SAMPLES "/sunset.png"); !s)
        return state.SkipWithError(s.error().message.c_str());
    if (Status s = doc.loadPreset(preset); !s)
        return state.SkipWithError(s.error().message.c_str());
    Preview preview;
    preview.fit(doc, 1280, 720);
    float x = 200;
    for (auto _ : state) {
        doc.light = {x, 260.f};  // a new place each frame, as in a drag
        x = x > 1100 ? 200 : x + 7;
        auto frame = layers ? preview.renderComponents(doc) : preview.render(doc);
        if (!frame) return state.SkipWithError(frame.error().message.c_str());
        benchmark::DoNotOptimize(frame);
    }
    state.counters["frames/s"] =
        benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
    const std::int64_t pixels = layers
                                    ? std::int64_t(kComponentWidth) * kComponentWidth * 720 / 1280
                                    : std::int64_t(preview.width()) * preview.height();
    state.SetItemsProcessed(state.iterations() * pixels);
}

void registerAll() {
    for (const std::string& name : shippedPresetNames()) {
        benchmark::RegisterBenchmark(("BM_StudioDrag/" + name).c_str(), previewUpdate, name, false)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_StudioRefine/" + name).c_str(), previewUpdate, name, true)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

}  // namespace

int main(int argc, char** argv) {
    registerAll();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
