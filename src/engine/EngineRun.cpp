// SPDX-License-Identifier: Apache-2.0
#include "flarekit/gl/EngineRun.h"

#include <chrono>
#include <map>
#include <memory>

#include "engine/EngineRunLights.h"
#include "engine/vulkan/VulkanRun.h"
#include "flarekit/flarekit.h"
#include "flarekit/gl/GpuTimer.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit {

namespace {
struct EngineDeleter {
    void operator()(fk_engine* e) const { fk_engine_destroy(e); }
};
}  // namespace

Result<std::vector<fk_light>> sceneEngineLights(fk_engine* e, const Scene& scene,
                                                const EngineRunOptions& o) {
    // Each preset named by a light, loaded once (only when flares are drawn); the first light
    // whose preset fails to load names itself.
    std::map<std::string, int> ids;
    if (o.flares) {
        const std::vector<SceneLight> sceneLightList = sceneLights(scene);
        for (std::size_t i = 0; i < sceneLightList.size(); ++i) {
            const std::string& name = sceneLightList[i].preset;
            if (name.empty() || ids.count(name)) continue;
            const int id = fk_engine_load_preset(e, name.c_str());
            if (id < 0) {
                return invalidInput(o.source + ": lights[" + std::to_string(i) +
                                    "].preset: " + fk_error(e));
            }
            ids[name] = id;
        }
    }
    const std::vector<fk_light> lights = engineLights(scene, [&](const std::string& name) {
        const auto it = ids.find(name);
        return it == ids.end() ? -1 : it->second;
    });
    return lights;
}

Result<EngineRun> runEngineScene(const Scene& scene, const EngineRunOptions& o) {
    auto context = gl::createFrameContext(scene.width, scene.height, o.render.msaaSamples,
                                          o.source + ": image");
    if (!context) return context.error();
    auto renderer = SceneRenderer::create(scene, o.render);
    if (!renderer) return renderer.error();
    if (Status s = renderer->draw(scene); !s) return s.error();
    if (o.backend == "vulkan") return vk::runEngineSceneOnVulkan(scene, o, *renderer);
    const std::size_t count = sceneLights(scene).size();
    std::unique_ptr<fk_engine, EngineDeleter> engine(fk_engine_create(int(count)));
    if (!engine) return internalError(fk_error(nullptr));
    fk_engine* e = engine.get();
    if (fk_engine_set_method(e, o.method.c_str()) < 0 ||
        fk_engine_set_samples(e, o.measure.samplesPerSide) < 0 ||
        fk_engine_set_tile_threshold(e, o.measure.tileBelowSamples) < 0)
        return invalidInput(fk_error(e));
    // The sun maps (every light with texture-mask, the small ones with compute) get the
    // scene's objects from the occluder callback, as an application's would.
    auto occluders = SceneOccluders::create(scene);
    if (!occluders) return occluders.error();
    fk_engine_set_occluder_callback(e, &SceneOccluders::draw, occluders->get());
    auto lightList = sceneEngineLights(e, scene, o);
    if (!lightList) return lightList.error();
    const std::vector<fk_light>& lights = *lightList;
    const fk_frame frame = engineFrame(scene, *renderer);
    if (fk_engine_set_transmittance(e, 0, engineTransmittance(*renderer)) < 0)
        return internalError(fk_error(e));

    EngineRun run;
    run.renderer = (*context)->renderer();
    const GpuTimer occlusionTimer, drawTimer;
    const auto start = std::chrono::steady_clock::now();
    occlusionTimer.begin();
    const int measured = fk_engine_occlusion(e, &frame, lights.data(), int(lights.size()));
    occlusionTimer.end();
    if (measured < 0) return invalidInput(o.source + ": " + fk_error(e));
    if (o.flares) {
        drawTimer.begin();
        const int drawn = fk_engine_draw(e, &frame, lights.data(), int(lights.size()),
                                         engineColorFramebuffer(*renderer));
        drawTimer.end();
        if (drawn < 0) return invalidInput(o.source + ": " + fk_error(e));
    }
    run.cpuMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    run.occlusionGpuMs = occlusionTimer.milliseconds();
    if (o.flares) run.drawGpuMs = drawTimer.milliseconds();
    std::vector<float> coverage(lights.size()), inFrame(lights.size());
    if (fk_engine_read_view(e, 0, coverage.data(), inFrame.data(), nullptr, int(lights.size())) < 0)
        return internalError(fk_error(e));
    for (std::size_t i = 0; i < lights.size(); ++i)
        run.lights.push_back({double(coverage[i]), double(inFrame[i])});
    if (o.flares) {
        auto image = renderer->readColor();
        if (!image) return image.error();
        run.image = std::move(*image);
    }
    return run;
}

}  // namespace flarekit
