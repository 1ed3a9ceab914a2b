// SPDX-License-Identifier: Apache-2.0
// The studio's preview update (on the CPU, and with the view's backend gl through flarekit's GL
// backend, where it applies), as the window makes it while the light is dragged
// (the view: the image with its flare at 1280x720, the sample photograph at its own size) and
// when it stops (the component passes, each 320 pixels wide), for each shipped sprite preset;
// each post-process preset's view, and a lens's view while dragged and when the drag stops.
// frames/s is what the view can follow; the window's own drawing (Dear ImGui on llvmpipe) comes on
// top, and is measured by `flarekit studio --stats` (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <string>

#include "Document.h"
#include "Preview.h"

using namespace flarekit;
using namespace flarekit::studio;

namespace {

void previewUpdate(benchmark::State& state, FlareKind kind, const std::string& preset, bool layers,
                   bool dragging, ViewBackend backend) {
    Document doc;
    doc.view.backend = backend;
    if (Status s = doc.openImage(FLAREKIT_SAMPLES "/sunset.png"); !s)
        return state.SkipWithError(s.error().message.c_str());
    doc.kind = kind;
    if (Status s = doc.loadPreset(preset); !s)
        return state.SkipWithError(s.error().message.c_str());
    Preview preview;
    preview.fit(doc, 1280, 720);
    preview.dragging = dragging;
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

void add(const std::string& name, FlareKind kind, const std::string& preset, bool layers,
         bool dragging, ViewBackend backend = ViewBackend::Cpu) {
    benchmark::RegisterBenchmark(name.c_str(), previewUpdate, kind, preset, layers, dragging,
                                 backend)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
}

void registerAll() {
    for (const std::string& name : shippedPresetNames()) {
        add("BM_StudioDrag/" + name, FlareKind::Sprite, name, false, true);
        add("BM_StudioRefine/" + name, FlareKind::Sprite, name, true, false);
    }
    // A post-process flare does not follow the light: an update is an edit of the preset.
    for (const std::string& name : shippedPostFxPresetNames()) {
        add("BM_StudioPostFx/" + name, FlareKind::PostFx, name, false, false);
        add("BM_StudioPostFxGl/" + name, FlareKind::PostFx, name, false, false, ViewBackend::Gl);
    }
    // A lens while the light is dragged (its 8 brightest ghosts, coarse meshes) and when it
    // stops (every ghost of the render settings, 66 by default).
    for (const char* lens : {"angenieux-double-gauss", "canon-zoom-70-210"}) {
        add(std::string("BM_StudioLensDrag/") + lens, FlareKind::Lens, lens, false, true);
        add(std::string("BM_StudioLensFull/") + lens, FlareKind::Lens, lens, false, false);
        add(std::string("BM_StudioLensDragGl/") + lens, FlareKind::Lens, lens, false, true,
            ViewBackend::Gl);
        add(std::string("BM_StudioLensFullGl/") + lens, FlareKind::Lens, lens, false, false,
            ViewBackend::Gl);
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
