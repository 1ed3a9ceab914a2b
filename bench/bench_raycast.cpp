// SPDX-License-Identifier: Apache-2.0
// Ray-cast ground truth: rays per second on 1 and 2 threads, on the demo world (BVH built once,
// the camera driving along the road) and on a denser synthetic foliage scene (24 trees of 400
// leaf triangles, trunks, buildings; the BVH rebuilt per call as `flarekit visibility` does).
#include <benchmark/benchmark.h>

#include <random>

#include "core/Parallel.h"
#include "flarekit/Demo.h"
#include "flarekit/Visibility.h"

using namespace flarekit;

namespace {

Scene foliage() {
    Scene s;
    s.camera.position = {0, 1.7, 0};
    s.camera.lookAt = {0, 5, -20};
    s.sun.direction = normalize(Vec3{0.25, 0.35, -1});
    s.sun.angularRadiusDeg = 1.5;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int tree = 0; tree < 24; ++tree) {
        const double side = tree % 2 ? 6 : -6, z = -10 - 8.0 * (tree / 2);
        s.boxes.push_back({{side - 0.2, 0, z - 0.2}, {side + 0.2, 4, z + 0.2}, {}});
        for (int leaf = 0; leaf < 400; ++leaf) {
            const Vec3 c{side + 2.5 * u(rng), 6 + 2.5 * u(rng), z + 2.5 * u(rng)};
            s.triangles.push_back({c,
                                   c + Vec3{0.4 * u(rng), 0.4 * u(rng), 0.4 * u(rng)},
                                   c + Vec3{0.4 * u(rng), 0.4 * u(rng), 0.4 * u(rng)},
                                   {}});
        }
    }
    for (int b = 0; b < 8; ++b)
        s.boxes.push_back({{-30.0 + 8 * b, 0, -120}, {-25.0 + 8 * b, 15.0 + b, -110}, {}});
    return s;
}

void BM_Raycast(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    const Scene scene = foliage();
    RaycastOptions options;
    std::size_t rays = 0;
    double coverage = 0;
    for (auto _ : state) {
        auto r = raycastVisibility(scene, options);
        rays = r->samples;
        coverage = r->coverage;
    }
    state.counters["rays/s"] =
        benchmark::Counter(double(rays), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["coverage"] = coverage;
    state.counters["triangles"] = double(scene.triangles.size());
}
BENCHMARK(BM_Raycast)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

//! The demo's drive: 64 camera positions cycled, 128^2 rays each (the default ground truth).
void BM_RaycastDemo(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    const Scene world = demoScene(1280, 720, 0);
    const RaycastCaster caster(world);
    std::vector<Scene> views;
    for (int i = 0; i < 64; ++i) {
        Scene v = demoScene(1280, 720, i / 64.0);
        v.spheres.clear(), v.boxes.clear(), v.triangles.clear();
        views.push_back(std::move(v));
    }
    std::size_t rays = 0, frame = 0;
    for (auto _ : state) {
        auto r = caster.measure(views[frame++ % views.size()]);
        rays += r->samples;
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["primitives"] = double(caster.primitiveCount());
}
BENCHMARK(BM_RaycastDemo)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DemoBvhBuild(benchmark::State& state) {
    const Scene world = demoScene(1280, 720, 0);
    for (auto _ : state) {
        RaycastCaster caster(world);
        benchmark::DoNotOptimize(caster);
    }
}
BENCHMARK(BM_DemoBvhBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
