// SPDX-License-Identifier: Apache-2.0
#include "flarekit/gl/EngineScene.h"

#include <algorithm>

#include "scene/CameraMath.h"
#include "scene/SceneTargets.h"

namespace flarekit {

namespace {
void copy3(float* to, Vec3 v) {
    to[0] = float(v.x), to[1] = float(v.y), to[2] = float(v.z);
}
}  // namespace

std::vector<fk_light> engineLights(const Scene& scene,
                                   const std::function<int(const std::string&)>& presetId) {
    std::vector<fk_light> out;
    for (const SceneLight& l : sceneLights(scene)) {
        fk_light f{};
        const bool point = l.type == LightType::Point;
        f.type = point ? FK_LIGHT_POINT : FK_LIGHT_DIRECTIONAL;
        copy3(f.position, l.position);
        copy3(f.direction, l.direction);
        f.radius = float(point ? l.radius : l.angularRadiusDeg);
        copy3(f.color, l.color);
        f.intensity = float(l.intensity);
        f.preset = l.preset.empty() ? -1 : presetId(l.preset);
        out.push_back(f);
    }
    return out;
}

fk_frame engineFrame(const Scene& scene, const SceneRenderer& renderer, float dtSeconds) {
    const SceneTargets t = sceneTargets(renderer);
    fk_frame f{};
    f.depth_texture = t.msaaSamples > 1 ? t.multisampleDepth : t.depth;
    f.width = renderer.width();
    f.height = renderer.height();
    f.viewport[2] = f.width;
    f.viewport[3] = f.height;
    f.depth_convention = FK_DEPTH_MINUS_ONE_TO_ONE;
    const auto view = toFloat(lookAtMatrix(scene.camera));
    const auto projection =
        toFloat(perspectiveMatrix(scene.camera, double(f.width) / double(f.height)));
    std::copy(view.begin(), view.end(), f.view);
    std::copy(projection.begin(), projection.end(), f.projection);
    f.dt_seconds = dtSeconds;
    return f;
}

unsigned engineTransmittance(const SceneRenderer& renderer) {
    return sceneTargets(renderer).transmittance;
}

unsigned engineColorFramebuffer(const SceneRenderer& renderer) {
    return sceneTargets(renderer).framebuffer;
}

}  // namespace flarekit
