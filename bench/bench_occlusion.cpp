// SPDX-License-Identifier: Apache-2.0
// The seed's experiment, and past it. GPG2's texture-masking article measured 27.8
// frames/s with the "lock" (synchronous depth read-back) against 53.5 with texture masking at
// 600x500, and explained the gap: the lock makes the CPU wait for the GPU to finish the frame,
// so game work on the CPU and rendering on the GPU take turns instead of overlapping. Its demo
// had an "Increase CPU Work" key; here that is the second argument, milliseconds of simulated
// game work spun on the CPU every frame.
//
// Every frame of BM_FrameLoop/<method>/<cpu work ms>: game work, scene draw (the demo drive,
// 600x500), the method's measure(), the GPU temporal filter, the GPU sprite flare reading the
// filtered weight, the GPU tone map; then the swap chain's throttle: at most two frames in
// flight (a fence per frame, waited two frames later), as a double-buffered swap would.
// Counters:
//   fps              frames per second of wall time
//   measure_cpu_ms   CPU time inside measure() (the lock's stall shows here)
//   gl_cpu_ms        CPU time inside all of the frame's GL calls (draw, measure, filter, flare,
//                    tone map): near zero on a GPU for the non-stalling methods; llvmpipe bins
//                    on the calling thread and waits for pending scenes whenever a pass samples
//                    a texture an earlier pass rendered, so there it is most of the frame
//   throttle_ms      CPU time waiting for the GPU at the throttle (GPU-bound frames)
//   gpu_ms           GPU time of measure()'s commands (GL_TIME_ELAPSED; unreliable on llvmpipe,
//                    whose "GPU" is threads on the same cores)
//   latency_frames   frames between a frame and its result reaching the flare
//   err_mean/err_max |coverage - raycast| over 24 drive frames with the disc fully in frame
#include <benchmark/benchmark.h>

#include <epoxy/gl.h>

#include <array>
#include <chrono>
#include <cmath>
#include <map>

#include <epoxy/gl.h>
#include "flarekit/Demo.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/GpuFlare.h"
#include "flarekit/gl/GpuVisibility.h"

#include "flarekit/gl/GpuTimer.h"
#include "flarekit/gl/HeadlessGl.h"
#include "scene/CameraMath.h"

using namespace flarekit;

namespace {

//! GPG2's test resolution.
constexpr int kWidth = 600, kHeight = 500;
constexpr int kViews = 240;
constexpr int kFramesInFlight = 2;

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

gl::HeadlessGl* context() {
    static auto gl = gl::HeadlessGl::create();
    return gl ? gl->get() : nullptr;
}

//! Busy work standing in for a game's update: the CPU is occupied, not sleeping.
void spinFor(double ms) {
    const auto end = Clock::now() + std::chrono::duration<double, std::milli>(ms);
    volatile double x = 1.0;
    while (Clock::now() < end) {
        for (int i = 0; i < 256; ++i) x = x * 1.0000001 + 1e-9;
    }
}

std::vector<Scene> driveViews(int count) {
    std::vector<Scene> views;
    for (int i = 0; i < count; ++i) {
        Scene v = demoScene(kWidth, kHeight, double(i) / count);
        v.spheres.clear(), v.boxes.clear(),
            v.triangles.clear();  // draw() reads only camera and sun
        views.push_back(std::move(v));
    }
    return views;
}

struct Accuracy {
    double mean = 0, max = 0;
};

//! |method - raycast| over 24 frames of the drive whose disc is fully in frame.
Accuracy accuracyOnDrive(const std::string& name, const Scene& world, SceneRenderer& renderer) {
    static std::map<std::string, Accuracy> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second;
    auto method = createGpuVisibility(name, world);
    RaycastCaster caster(world);
    Accuracy a;
    int n = 0;
    for (int i = 0; i < 24; ++i) {
        Scene view = demoScene(kWidth, kHeight, (i + 0.5) / 24);
        view.spheres.clear(), view.boxes.clear(), view.triangles.clear();
        if (sunInFrameFraction(view) < 0.999) continue;
        RaycastOptions rays;
        rays.samplesPerSide = 128;
        auto truth = caster.measure(view, rays);
        auto got = measureStillFrame(**method, renderer, view);
        if (!truth || !got) continue;
        const double e = std::fabs(*got - truth->coverage);
        a.mean += e, a.max = std::max(a.max, e), ++n;
    }
    if (n) a.mean /= n;
    return cache[name] = a;
}

void BM_FrameLoop(benchmark::State& state, const std::string& name) {
    gl::HeadlessGl* gl = context();
    if (!gl) {
        state.SkipWithError("no headless GL");
        return;
    }
    const double workMs = double(state.range(0));
    const Scene world = demoScene(kWidth, kHeight, 0);
    auto renderer = SceneRenderer::create(world);
    auto method = createGpuVisibility(name, world);
    auto preset = loadPreset("tanczos-classic");
    auto filter = GpuTemporalFilter::create();
    auto tonemap = GpuTonemap::create(kWidth, kHeight);
    if (!renderer || !method || !preset || !filter || !tonemap) {
        state.SkipWithError("setup failed");
        return;
    }
    auto flare = GpuSpriteFlare::create(*preset, kHeight);
    if (!flare) {
        state.SkipWithError(flare.error().message.c_str());
        return;
    }
    const Accuracy accuracy = accuracyOnDrive(name, world, *renderer);
    const std::vector<Scene> views = driveViews(kViews);

    std::array<GLsync, kFramesInFlight> fences{};
    std::array<GpuTimer, kFramesInFlight> timers;
    double measureMs = 0, glMs = 0, throttleMs = 0, gpuMs = 0;
    long frame = 0, timed = 0;
    const double dt = kDemoDurationSeconds / kViews;
    for (auto _ : state) {
        const std::size_t slot = std::size_t(frame % kFramesInFlight);
        // The throttle: the frame that used this slot two frames ago must be done.
        if (fences[slot]) {
            const auto t = Clock::now();
            glClientWaitSync(fences[slot], GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(10'000'000'000));
            throttleMs += msSince(t);
            glDeleteSync(fences[slot]);
            gpuMs += timers[slot].milliseconds();  // finished: reading does not wait
            ++timed;
        }
        spinFor(workMs);  // the game's update for this frame
        const Scene& view = views[std::size_t(frame % kViews)];
        Point sun;
        const bool inFront =
            projectDirection(view, view.sun.direction, sun);  // camera maths, no GPU
        const auto frameStart = Clock::now();
        (void)renderer->draw(view);
        const auto t = Clock::now();
        timers[slot].begin();
        (void)(*method)->measure(view, *renderer);
        timers[slot].end();
        measureMs += msSince(t);
        (void)filter->update((*method)->coverage(), sun, inFront, kWidth, kHeight,
                             frame ? dt : 0.0);
        (void)flare->draw(*renderer, view, filter->state(GpuStateChannel::FlareWeight));
        (void)tonemap->apply(*renderer, filter->state(GpuStateChannel::Exposure));
        fences[slot] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        glFlush();
        glMs += msSince(frameStart);
        ++frame;
    }
    glFinish();
    for (GLsync f : fences)
        if (f) glDeleteSync(f);
    const double n = double(state.iterations());
    state.counters["fps"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
    state.counters["measure_cpu_ms"] = measureMs / n;
    state.counters["gl_cpu_ms"] = glMs / n;
    state.counters["throttle_ms"] = throttleMs / n;
    state.counters["gpu_ms"] = timed ? gpuMs / double(timed) : 0.0;
    state.counters["latency_frames"] = (*method)->latencyFrames();
    state.counters["err_mean"] = accuracy.mean;
    state.counters["err_max"] = accuracy.max;
    state.SetLabel(gl->renderer());
}

}  // namespace

int main(int argc, char** argv) {
    for (const std::string& name : gpuVisibilityMethods()) {
        auto* b =
            benchmark::RegisterBenchmark(("BM_FrameLoop/" + name).c_str(),
                                         [name](benchmark::State& s) { BM_FrameLoop(s, name); });
        b->ArgName("cpu_work_ms")->Arg(0)->Arg(10)->Arg(20)->Arg(40);
        b->Iterations(90)->Unit(benchmark::kMillisecond)->UseRealTime();
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
