// SPDX-License-Identifier: Apache-2.0
// The demo's frame loop: the camera along the road, each frame through the frame pipeline
// (scene pass, sun visibility, temporal filter, sprite flare, tone map).
#include <algorithm>

#include "demo/DemoWorld.h"
#include "flarekit/Demo.h"
#include "flarekit/gl/DemoAnimation.h"
#include "flarekit/gl/FramePipeline.h"

namespace flarekit {

struct DemoAnimation::Impl {
    DemoSettings settings;
    Scene view;  // no objects: they are uploaded to the pipeline once
    FramePipeline pipeline;
    int nextFrame = 0;
};

DemoAnimation::DemoAnimation(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
DemoAnimation::~DemoAnimation() = default;
DemoAnimation::DemoAnimation(DemoAnimation&&) noexcept = default;
DemoAnimation& DemoAnimation::operator=(DemoAnimation&&) noexcept = default;

int DemoAnimation::frameCount() const {
    return m->settings.frames;
}
std::size_t DemoAnimation::primitiveCount() const {
    return m->pipeline.primitiveCount();
}

Result<DemoAnimation> DemoAnimation::create(const DemoSettings& settings, const Preset& preset) {
    if (Status s = validateDemoSettings(settings); !s) return s.error();
    const Scene world = demo::buildWorld(settings.width, settings.height);
    FramePipelineSettings frames;
    frames.method = settings.method;
    frames.raycastSamplesPerSide = settings.raycastSamplesPerSide;
    frames.render.msaaSamples = settings.msaaSamples;
    frames.temporalParams = settings.temporal;
    frames.conditionalRender = settings.conditionalRender;
    frames.methodViews = settings.methodViews;
    auto pipeline = FramePipeline::create(world, preset, frames);
    if (!pipeline) return pipeline.error();
    Scene view;
    view.width = world.width, view.height = world.height, view.sun = world.sun;
    return DemoAnimation(
        std::make_unique<Impl>(Impl{settings, std::move(view), std::move(*pipeline), 0}));
}

Result<DemoFrame> DemoAnimation::next() {
    Impl& d = *m;
    if (d.nextFrame >= d.settings.frames) return invalidInput("demo: no frame after the last");
    const int index = d.nextFrame++;
    // Frame i shows time i / fps (240 frames at 30 fps: the 8 s drive); past its end the
    // camera stays at the last position.
    const double time = double(index) / d.settings.fps;
    const double t = std::min(1.0, time / kDemoDurationSeconds);
    const double dt = index == 0 ? 0.0 : 1.0 / d.settings.fps;
    d.view.camera = demo::cameraAt(t);
    // A fresh raycast jitter each frame: the noise averages out over time.
    auto frame = d.pipeline.run(d.view, dt, std::uint64_t(index) + 1);
    if (!frame) return frame.error();
    DemoFrame out;
    static_cast<PipelineFrame&>(out) = std::move(*frame);
    out.time = time;
    return out;
}

}  // namespace flarekit
