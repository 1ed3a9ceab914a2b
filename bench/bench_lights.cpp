// SPDX-License-Identifier: Apache-2.0
// The engine API's cost per frame for many lights at 1920x1080 (4x MSAA depth): one
// fk_engine_occlusion (every light in one dispatch) and one fk_engine_draw (every flare,
// instanced per element), against the same lights measured one call each.
//   BM_Occlusion/<lights>        one batched occlusion call a frame
//   BM_Draw/<lights>             one flare draw call a frame (subtle preset: 4 elements)
//   BM_OcclusionOneByOne/<lights> the same lights, one fk_engine_occlusion call per light
//   BM_TextureMask/<lights>      texture-mask: a sun map per light drawn by the occluder
//                                callback (flarekit's SceneOccluders: the whole scene a light)
//   BM_OcclusionWithTiles/<lights> compute with the occluder callback set: lights under
//                                1,024 depth samples from sun maps, the rest on the depth
// Counters (means per frame):
//   cpu_ms   wall time inside the API call(s): what the application's render thread pays
//   gpu_ms   GPU time of the call(s), from timestamp queries around them
//   wall_ms  the call(s) plus glFinish: the frame's share end to end
// On llvmpipe the "GPU" is threads on the same cores and GL calls may run work on the calling
// thread, so cpu_ms there includes GPU work; on a GPU driver it is the API's own cost.
#include <benchmark/benchmark.h>

#include <epoxy/gl.h>

#include <chrono>
#include <memory>

#include "LightScenes.h"
#include "engine/EngineInput.h"
#include "flarekit/flarekit.h"
#include "flarekit/gl/EngineScene.h"
#include "flarekit/gl/GpuTimer.h"
#include "flarekit/gl/HeadlessGl.h"
#include "flarekit/gl/Render.h"

using namespace flarekit;

namespace {

constexpr int kWidth = 1920, kHeight = 1080, kMaxLights = 4096;
using Clock = std::chrono::steady_clock;

struct Bench {
    std::unique_ptr<gl::HeadlessGl> gl;
    std::unique_ptr<SceneRenderer> renderer;
    Scene scene;
    fk_engine* engine = nullptr;
    std::vector<fk_light> lights;
    fk_frame frame{};
    std::string error;
};

void setUp(Bench& s) {
    auto gl = gl::HeadlessGl::create();
    if (!gl) {
        s.error = gl.error().message;
        return;
    }
    s.gl = std::move(*gl);
    s.scene = test::lampScene(kMaxLights, 17, true, kWidth, kHeight);
    RenderOptions options;
    options.msaaSamples = 4;
    options.shadows = false;
    auto renderer = SceneRenderer::create(s.scene, options);
    if (!renderer) {
        s.error = renderer.error().message;
        return;
    }
    s.renderer = std::make_unique<SceneRenderer>(std::move(*renderer));
    if (Status st = s.renderer->draw(s.scene); !st) {
        s.error = st.error().message;
        return;
    }
    s.engine = fk_engine_create(kMaxLights);
    if (!s.engine) {
        s.error = fk_error(nullptr);
        return;
    }
    const int preset = fk_engine_load_preset(s.engine, "subtle");
    s.lights = engineLights(s.scene, [preset](const std::string&) { return preset; });
    s.frame = engineFrame(s.scene, *s.renderer, 1.f / 60.f);
    fk_engine_set_transmittance(s.engine, 0, engineTransmittance(*s.renderer));
    glFinish();
}

Bench& bench() {
    static Bench b;
    static const bool ready = (setUp(b), true);
    (void)ready;
    return b;
}

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

//! Runs `call` once per iteration with the counters above; `calls` is how many API calls it
//! makes (for the per-call CPU figure).
template <class Call>
void measure(benchmark::State& state, Call call) {
    Bench& b = bench();
    if (!b.engine) return state.SkipWithError(b.error.c_str());
    call(b);  // warm-up: shader variants compile on first use on some drivers
    glFinish();
    double cpu = 0, gpu = 0, wall = 0;
    const GpuTimer timer;
    for (auto _ : state) {
        const auto start = Clock::now();
        timer.begin();
        if (!call(b)) return state.SkipWithError(fk_error(b.engine));
        timer.end();
        cpu += msSince(start);
        glFinish();
        wall += msSince(start);
        gpu += timer.milliseconds();
        state.SetIterationTime(msSince(start) / 1000.0);
    }
    const double n = double(state.iterations());
    state.counters["cpu_ms"] = cpu / n;
    state.counters["gpu_ms"] = gpu / n;
    state.counters["wall_ms"] = wall / n;
    state.counters["lights"] = double(state.range(0));
}

void BM_Occlusion(benchmark::State& state) {
    const int count = int(state.range(0));
    measure(state, [count](Bench& b) {
        return fk_engine_occlusion(b.engine, &b.frame, b.lights.data(), count) == 0;
    });
}

void BM_Draw(benchmark::State& state) {
    const int count = int(state.range(0));
    Bench& b = bench();
    if (b.engine) fk_engine_occlusion(b.engine, &b.frame, b.lights.data(), count);
    measure(state, [count](Bench& x) {
        return fk_engine_draw(x.engine, &x.frame, x.lights.data(), count,
                              engineColorFramebuffer(*x.renderer)) == 0;
    });
}

void BM_OcclusionOneByOne(benchmark::State& state) {
    const int count = int(state.range(0));
    measure(state, [count](Bench& b) {
        for (int i = 0; i < count; ++i)
            if (fk_engine_occlusion(b.engine, &b.frame, &b.lights[std::size_t(i)], 1) != 0)
                return false;
        return true;
    });
}

//! The API's own CPU work per call, without the driver: every light's arguments checked and
//! packed for upload (what remains of cpu_ms on a GPU driver besides a buffer copy and a
//! dispatch or a draw per preset element).
void BM_CheckAndPack(benchmark::State& state) {
    Bench& b = bench();
    if (!b.engine) return state.SkipWithError(b.error.c_str());
    const int count = int(state.range(0));
    std::vector<float> packed;
    for (auto _ : state) {
        const Status s = engine::checkLights(b.lights.data(), count, kMaxLights, 1);
        engine::packLights(b.lights.data(), count, packed);
        benchmark::DoNotOptimize(packed.data());
        if (!s) return state.SkipWithError(s.error().message.c_str());
    }
    state.counters["lights"] = double(count);
}

void BM_TextureMask(benchmark::State& state) {
    const int count = int(state.range(0));
    Bench& b = bench();
    if (!b.engine) return state.SkipWithError(b.error.c_str());
    static auto occluders = SceneOccluders::create(b.scene);
    if (!occluders) return state.SkipWithError(occluders.error().message.c_str());
    fk_engine_set_occluder_callback(b.engine, &SceneOccluders::draw, occluders->get());
    fk_engine_set_method(b.engine, "texture-mask");
    measure(state, [count](Bench& x) {
        return fk_engine_occlusion(x.engine, &x.frame, x.lights.data(), count) == 0;
    });
    fk_engine_set_method(b.engine, "compute");
    fk_engine_set_occluder_callback(b.engine, nullptr, nullptr);
}

//! Counts the callback's calls: the lights measured from sun maps.
struct CountedOccluders {
    SceneOccluders* scene = nullptr;
    long long calls = 0;
    static void draw(void* user, int view, int light, const float* vp, unsigned fb,
                     const int* viewport) {
        auto* self = static_cast<CountedOccluders*>(user);
        ++self->calls;
        SceneOccluders::draw(self->scene, view, light, vp, fb, viewport);
    }
};

void BM_OcclusionWithTiles(benchmark::State& state) {
    const int count = int(state.range(0));
    Bench& b = bench();
    if (!b.engine) return state.SkipWithError(b.error.c_str());
    static auto occluders = SceneOccluders::create(b.scene);
    if (!occluders) return state.SkipWithError(occluders.error().message.c_str());
    static CountedOccluders counted;
    counted = {occluders->get(), 0};
    fk_engine_set_occluder_callback(b.engine, &CountedOccluders::draw, &counted);
    measure(state, [count](Bench& x) {
        return fk_engine_occlusion(x.engine, &x.frame, x.lights.data(), count) == 0;
    });
    state.counters["tiled"] = double(counted.calls) / double(state.iterations() + 1);
    fk_engine_set_occluder_callback(b.engine, nullptr, nullptr);
}

}  // namespace

BENCHMARK(BM_TextureMask)->Arg(16)->Arg(128)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OcclusionWithTiles)
    ->Arg(128)
    ->Arg(1024)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckAndPack)->Arg(1024)->Arg(4096)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Occlusion)
    ->Arg(1)
    ->Arg(16)
    ->Arg(128)
    ->Arg(1024)
    ->Arg(4096)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Draw)->Arg(1)->Arg(16)->Arg(128)->Arg(1024)->Arg(4096)->UseManualTime()->Unit(
    benchmark::kMillisecond);
BENCHMARK(BM_OcclusionOneByOne)->Arg(1024)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
