// The demo's frame loop: camera along the road, GL scene pass, sun visibility, the temporal
// filter (smoothed coverage, edge fade, exposure), the sprite flare, tone mapping.
#include <chrono>

#include "demo/DemoWorld.h"
#include "flarekit/Demo.h"
#include "flarekit/Render.h"
#include "flarekit/Tonemap.h"
#include "flarekit/Visibility.h"
#include "scene/CameraMath.h"

namespace flarekit {

Scene demoScene(int width, int height, double t) {
    Scene s = demo::buildWorld(width, height);
    s.camera = demo::cameraAt(t);
    return s;
}

struct DemoAnimation::Impl {
    Impl(DemoSettings s, Preset p, Scene w, SceneRenderer r)
        : settings(std::move(s)), preset(std::move(p)), world(std::move(w)), renderer(std::move(r)), caster(world),
          filter(settings.temporal) {
        view.width = world.width, view.height = world.height, view.sun = world.sun;
    }
    DemoSettings settings;
    Preset preset;
    Scene world;
    Scene view;  // no objects: they are uploaded to the renderer and in the caster's BVH
    SceneRenderer renderer;
    RaycastCaster caster;
    TemporalFilter filter;
    int nextFrame = 0;
};

DemoAnimation::DemoAnimation(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
DemoAnimation::~DemoAnimation() = default;
DemoAnimation::DemoAnimation(DemoAnimation&&) noexcept = default;
DemoAnimation& DemoAnimation::operator=(DemoAnimation&&) noexcept = default;

int DemoAnimation::frameCount() const { return m->settings.frames; }
std::size_t DemoAnimation::primitiveCount() const { return m->caster.primitiveCount(); }

Status validateDemoSettings(const DemoSettings& settings) {
    if (settings.frames < 1 || settings.frames > 100000) {
        return invalidInput("frames: expected an integer in [1, 100000], got " + std::to_string(settings.frames));
    }
    if (settings.width < 16 || settings.height < 16 || settings.width > 16384 || settings.height > 16384) {
        return invalidInput("size: expected each side in [16, 16384], got " + std::to_string(settings.width) + "x" +
                            std::to_string(settings.height));
    }
    if (settings.method != "raycast") {
        return invalidInput("method: '" + settings.method + "' is not available for the demo yet; available: raycast");
    }
    if (settings.raycastSamplesPerSide < 1 || settings.raycastSamplesPerSide > 4096) {
        return invalidInput("samples: expected an integer in [1, 4096], got " +
                            std::to_string(settings.raycastSamplesPerSide));
    }
    return validateTemporalParams(settings.temporal);
}

Result<DemoAnimation> DemoAnimation::create(const DemoSettings& settings, const Preset& preset) {
    if (Status s = validateDemoSettings(settings); !s) return s.error();
    Scene world = demo::buildWorld(settings.width, settings.height);
    auto renderer = SceneRenderer::create(world, {settings.msaaSamples});
    if (!renderer) return renderer.error();
    return DemoAnimation(std::make_unique<Impl>(settings, preset, std::move(world), std::move(*renderer)));
}

Result<DemoFrame> DemoAnimation::next() {
    Impl& d = *m;
    if (d.nextFrame >= d.settings.frames) return invalidInput("demo: no frame after the last");
    const int index = d.nextFrame++;
    // Frame i shows time i x dt with dt = duration / frames: 240 frames are 30 fps for 8 s.
    const double t = double(index) / d.settings.frames;
    const double dt = kDemoDurationSeconds / d.settings.frames;
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };

    Scene& view = d.view;  // camera, sun and size: what draw() and measure() read each frame
    view.camera = demo::cameraAt(t);
    DemoFrame frame;
    frame.time = t * kDemoDurationSeconds;

    const auto t0 = Clock::now();
    if (Status s = d.renderer.draw(view); !s) return s.error();
    auto image = d.renderer.readColor();
    if (!image) return image.error();
    const auto t1 = Clock::now();
    RaycastOptions rays;
    rays.samplesPerSide = d.settings.raycastSamplesPerSide;
    rays.seed = std::uint64_t(index) + 1;  // fresh jitter each frame: noise averages out over time
    auto visibility = d.caster.measure(view, rays);
    if (!visibility) return visibility.error();
    const auto t2 = Clock::now();

    frame.rawCoverage = visibility->coverage;
    frame.inFrame = visibility->inFrame;
    frame.sunInFront = projectDirection(view, view.sun.direction, frame.sunPixel);
    frame.temporal = d.filter.update(frame.rawCoverage, frame.sunPixel, frame.sunInFront, d.settings.width,
                                     d.settings.height, index == 0 ? 0.0 : dt);
    const FlaredFrame flare = addSunFlare(*image, view, d.preset, frame.temporal.flareWeight);
    frame.flareIntensity = flare.flareIntensity;
    tonemapAcesFitted(*image, float(frame.temporal.exposure));
    const auto t3 = Clock::now();
    frame.image = std::move(*image);
    frame.renderMs = ms(t0, t1);
    frame.visibilityMs = ms(t1, t2);
    frame.flareMs = ms(t2, t3);
    return frame;
}

}  // namespace flarekit
