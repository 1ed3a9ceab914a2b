// SPDX-License-Identifier: Apache-2.0
#include "flarekit/gl/SceneStill.h"

#include "flarekit/Visibility.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::gl {

FramePipelineSettings sceneStillSettings(const SceneStillOptions& o) {
    FramePipelineSettings settings;
    settings.method = o.method;
    settings.raycastSamplesPerSide = RaycastOptions{}.samplesPerSide;
    settings.render = o.render;
    settings.methodOptions.textureMaskVariant = o.variant;
    settings.temporal = false;
    settings.flare = o.flare;
    settings.toneMap = false;
    return settings;
}

Result<SceneStill> renderSceneStill(const SceneStillOptions& o) {
    if (Status s = checkVisibilityMethod(o.method); !s)
        return invalidInput("--" + s.error().message);  // `render`'s flag
    auto scene = loadScene(o.scene);
    if (!scene) return scene.error();
    auto preset = loadPreset(o.preset);
    if (!preset) return preset.error();
    if (Status s = checkFlareWork(*preset, scene->width, scene->height, 1, o.preset); !s)
        return s.error();
    auto gl =
        createFrameContext(scene->width, scene->height, o.render.msaaSamples, o.scene + ": image");
    if (!gl) return gl.error();
    auto pipeline = FramePipeline::create(*scene, *preset, sceneStillSettings(o));
    if (!pipeline) return pipeline.error();
    auto frame = pipeline->run(*scene, 0.0);
    if (!frame) return frame.error();
    return SceneStill{std::move(*frame), (*gl)->renderer(), (*gl)->platform()};
}

}  // namespace flarekit::gl
