// SPDX-License-Identifier: Apache-2.0
// The engine API's Vulkan backend per frame for many lights at 1920x1080 (4x MSAA depth drawn
// by a Vulkan depth pass, the lamps with the 4-element `subtle` preset), on whatever Vulkan
// device the loader gives first (Mesa's lavapipe without a GPU):
//   BM_VulkanFrame/<lights>   fk_engine_record_occlusion + fk_engine_record_draw in one
//                             command buffer, submitted and waited for
// Counters (means per frame):
//   cpu_ms   wall time inside the two record calls: what the application's render thread pays
//   gpu_ms   GPU time of the recorded commands, from timestamp queries around them
//   wall_ms  record, submit and wait: the frame's share end to end
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

#include "LightScenes.h"
#include "engine/vulkan/VulkanHost.h"
#include "engine/vulkan/VulkanRun.h"
#include "flarekit/flarekit_vulkan.h"
#include "flarekit/gl/EngineScene.h"
#include "scene/SceneMesh.h"

using namespace flarekit;

namespace {

constexpr int kWidth = 1920, kHeight = 1080, kMaxLights = 4096;
using Clock = std::chrono::steady_clock;

struct Bench {
    std::unique_ptr<vk::VulkanHost> host;
    fk_engine* engine = nullptr;
    Scene scene;
    std::vector<fk_light> lights;
    fk_frame frame{};
    vk::DepthImage depth;
    vk::Image color;
    std::string error;
};

void setUp(Bench& b) {
    auto host = vk::VulkanHost::create(false);
    if (!host) {
        b.error = host.error().message;
        return;
    }
    b.host = std::move(*host);
    b.scene = test::lampScene(kMaxLights, 17, false, kWidth, kHeight);
    const fk_vulkan_device device = b.host->engineDevice(2);
    b.engine = fk_engine_create_vulkan(&device, kMaxLights);
    if (!b.engine) {
        b.error = fk_error(nullptr);
        return;
    }
    const int preset = fk_engine_load_preset(b.engine, "subtle");
    b.lights = engineLights(b.scene, [preset](const std::string&) { return preset; });
    // The scene camera as a Vulkan application has it: [0, 1] depth, clip y down.
    const SceneCamera& c = b.scene.camera;
    const double f = 1.0 / std::tan(c.fovYDeg * 3.14159265358979 / 360.0);
    const double n = c.nearPlane, far = c.farPlane;
    fk_frame& fr = b.frame;
    fr.width = kWidth, fr.height = kHeight;
    fr.viewport[2] = kWidth, fr.viewport[3] = kHeight;
    fr.depth_convention = FK_DEPTH_ZERO_TO_ONE;
    fr.dt_seconds = 1.f / 60.f;
    const auto view = lookAtMatrix(c);
    for (int i = 0; i < 16; ++i) fr.view[i] = float(view[std::size_t(i)]);
    fr.projection[0] = float(f * kHeight / kWidth);
    fr.projection[5] = float(-f);
    fr.projection[10] = float(far / (n - far));
    fr.projection[11] = -1.f;
    fr.projection[14] = float(far * n / (n - far));
    const std::array<float, 16> vp = vk::viewProjection(fr);
    auto depth = b.host->depthImage(kWidth, kHeight, 4, VK_FORMAT_D32_SFLOAT);
    if (!depth) {
        b.error = depth.error().message;
        return;
    }
    b.depth = *depth;
    std::vector<float> mesh;
    for (const MeshVertex& v : buildSceneMesh(opaqueObjects(b.scene)))
        mesh.insert(mesh.end(), v.position, v.position + 3);
    if (Status s = b.host->drawDepth(b.depth, mesh, vp.data(), FK_DEPTH_ZERO_TO_ONE); !s) {
        b.error = s.error().message;
        return;
    }
    auto color = b.host->colorImage(VK_FORMAT_R16G16B16A16_SFLOAT, kWidth, kHeight, nullptr);
    if (!color) {
        b.error = color.error().message;
        return;
    }
    b.color = *color;
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

void BM_VulkanFrame(benchmark::State& state) {
    Bench& b = bench();
    if (!b.engine) return state.SkipWithError(b.error.c_str());
    const int count = int(state.range(0));
    fk_vulkan_frame vf{};
    vf.depth_view = b.depth.view;
    vf.depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    vf.depth_samples = VK_SAMPLE_COUNT_4_BIT;
    vf.color_view = b.color.view;
    vf.color_format = VK_FORMAT_R16G16B16A16_SFLOAT;
    vf.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    std::uint64_t frame = 0;
    double cpu = 0, gpu = 0, wall = 0;
    int rc = 0;
    const auto record = [&](VkCommandBuffer cmd) {
        vf.command_buffer = cmd;
        vf.frame_index = frame++;
        const auto start = Clock::now();
        rc |= fk_engine_record_occlusion(b.engine, &vf, &b.frame, b.lights.data(), count);
        rc |= fk_engine_record_draw(b.engine, &vf, &b.frame, b.lights.data(), count);
        cpu += msSince(start);
    };
    (void)b.host->submit(record);  // warm-up: sprites, pipelines
    cpu = 0;
    for (auto _ : state) {
        const auto start = Clock::now();
        auto ms = b.host->submitTimed(record);
        if (!ms || rc != 0)
            return state.SkipWithError(ms ? fk_error(b.engine) : ms.error().message.c_str());
        gpu += *ms;
        wall += msSince(start);
        state.SetIterationTime(msSince(start) / 1000.0);
    }
    const double n = double(state.iterations());
    state.counters["cpu_ms"] = cpu / n;
    state.counters["gpu_ms"] = gpu / n;
    state.counters["wall_ms"] = wall / n;
    state.counters["lights"] = double(count);
}

}  // namespace

BENCHMARK(BM_VulkanFrame)
    ->Arg(1)
    ->Arg(128)
    ->Arg(1024)
    ->Arg(4096)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
