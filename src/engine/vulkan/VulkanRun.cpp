// SPDX-License-Identifier: Apache-2.0
#include "engine/vulkan/VulkanRun.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>

#include "engine/EngineRunLights.h"
#include "engine/vulkan/VulkanHost.h"
#include "flarekit/flarekit_vulkan.h"
#include "gl/GlObjects.h"
#include "scene/SceneMesh.h"

namespace flarekit::vk {

namespace {

struct EngineDeleter {
    void operator()(fk_engine* e) const { fk_engine_destroy(e); }
};

//! The GL frame of engineFrame as a Vulkan application has it: depth mapped to [0, 1]
//! (clip z' = (z + w) / 2) and clip y flipped (Vulkan's y points down).
fk_frame vulkanFrame(fk_frame f) {
    for (int c = 0; c < 4; ++c) {
        float* column = f.projection + 4 * c;
        column[2] = 0.5f * (column[2] + column[3]);
        column[1] = -column[1];
    }
    f.depth_convention = FK_DEPTH_ZERO_TO_ONE;
    f.depth_texture = 0;
    return f;
}

std::vector<float> opaqueTriangles(const Scene& scene) {
    std::vector<float> xyz;
    for (const MeshVertex& v : buildSceneMesh(opaqueObjects(scene)))
        xyz.insert(xyz.end(), v.position, v.position + 3);
    return xyz;
}

}  // namespace

std::array<float, 16> viewProjection(const fk_frame& f) {
    std::array<float, 16> vp{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k)
                vp[std::size_t(4 * c + r)] += f.projection[4 * k + r] * f.view[4 * c + k];
    return vp;
}

Result<EngineRun> runEngineSceneOnVulkan(const Scene& scene, const EngineRunOptions& o,
                                         const SceneRenderer& renderer) {
    if (o.method != "compute") {
        return invalidInput(
            "--backend vulkan: expected --method compute (sun maps are drawn by "
            "the GL backend's occluder callback), got " +
            o.method);
    }
    const char* validate = std::getenv("FLAREKIT_VULKAN_VALIDATION");
    auto made = VulkanHost::create(validate && std::strcmp(validate, "1") == 0);
    if (!made) return made.error();
    VulkanHost& host = **made;
    const int count = int(sceneLights(scene).size());
    const fk_vulkan_device device = host.engineDevice(1);
    std::unique_ptr<fk_engine, EngineDeleter> engine(fk_engine_create_vulkan(&device, count));
    if (!engine) return internalError(fk_error(nullptr));
    fk_engine* e = engine.get();
    if (fk_engine_set_samples(e, o.measure.samplesPerSide) < 0 ||
        fk_engine_set_tile_threshold(e, o.measure.tileBelowSamples) < 0)
        return invalidInput(fk_error(e));
    // Small lights from sun maps, drawn with the scene's objects as an application's would.
    auto occluders = VulkanOccluders::create(host, scene);
    if (!occluders) return occluders.error();
    fk_engine_set_vulkan_occluder_callback(e, &VulkanOccluders::draw, occluders->get());
    auto lights = sceneEngineLights(e, scene, o);
    if (!lights) return lights.error();
    const fk_frame frame = vulkanFrame(engineFrame(scene, renderer));
    const int w = scene.width, h = scene.height;

    auto depth = host.depthImage(w, h, o.render.msaaSamples, VK_FORMAT_D32_SFLOAT);
    if (!depth) return depth.error();
    const std::unique_ptr<DepthImage, std::function<void(DepthImage*)>> depthOwner(
        &*depth, [&host](DepthImage* d) { host.destroy(*d); });
    const auto vp = viewProjection(frame);
    if (Status s = host.drawDepth(*depth, opaqueTriangles(scene), vp.data(), FK_DEPTH_ZERO_TO_ONE);
        !s)
        return s.error();
    fk_vulkan_frame vf{};
    vf.depth_view = depth->view;
    vf.depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    vf.depth_samples = VkSampleCountFlagBits(o.render.msaaSamples);
    // The renderer's transmittance and colour, rows from the top as Vulkan's y runs.
    Image transmittance, color;
    if (const unsigned t = engineTransmittance(renderer); t != 0) {
        auto pixels = gl::readTextureRgba(t, w, h);
        if (!pixels) return pixels.error();
        auto image = host.sampledImage(w, h, pixels->data());
        if (!image) return image.error();
        transmittance = *image;
        vf.transmittance_view = transmittance.view;
        vf.transmittance_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    }
    const auto release = [&] {
        host.device().destroy(transmittance);
        host.device().destroy(color);
    };
    if (o.flares) {
        auto pixels = renderer.readColor();
        if (!pixels) return release(), pixels.error();
        auto image = host.colorImage(VK_FORMAT_R32G32B32A32_SFLOAT, w, h, pixels->data());
        if (!image) return release(), image.error();
        color = *image;
        vf.color_view = color.view;
        vf.color_format = VK_FORMAT_R32G32B32A32_SFLOAT;
        vf.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    EngineRun run;
    run.renderer = "Vulkan: " + host.deviceName();
    int occluded = 0, drawn = 0;
    double recordMs = 0;
    // Each pass in its own timed submission (one frame: the draw reads the occlusion's
    // coverage), so the GPU times are the two passes' as the GL path reports them.
    const auto timed = [&](auto record, double& gpuMs) -> Status {
        auto ms = host.submitTimed([&](VkCommandBuffer cmd) {
            vf.command_buffer = cmd;
            const auto start = std::chrono::steady_clock::now();
            record();
            recordMs +=
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
        });
        if (!ms) return ms.error();
        gpuMs = *ms;
        return Ok{};
    };
    Status submitted =
        timed([&] { occluded = fk_engine_record_occlusion(e, &vf, &frame, lights->data(), count); },
              run.occlusionGpuMs);
    if (submitted && occluded == 0 && o.flares)
        submitted =
            timed([&] { drawn = fk_engine_record_draw(e, &vf, &frame, lights->data(), count); },
                  run.drawGpuMs);
    if (!submitted) return release(), submitted.error();
    if (occluded < 0 || drawn < 0) return release(), invalidInput(o.source + ": " + fk_error(e));
    run.cpuMs = recordMs;
    std::vector<float> coverage(static_cast<std::size_t>(count)), inFrame(coverage.size());
    if (fk_engine_read_view(e, 0, coverage.data(), inFrame.data(), nullptr, count) < 0)
        return release(), internalError(fk_error(e));
    for (int i = 0; i < count; ++i)
        run.lights.push_back({double(coverage[std::size_t(i)]), double(inFrame[std::size_t(i)])});
    if (o.flares) {
        auto pixels = host.readColor(color, w, h);
        if (!pixels) return release(), pixels.error();
        run.image = flarekit::Image(w, h);
        std::memcpy(run.image.data(), pixels->data(), pixels->size() * sizeof(float));
    }
    release();
    if (host.validationMessages() > 0)
        return internalError("Vulkan validation: " + host.firstValidationMessage());
    return run;
}

}  // namespace flarekit::vk
