// The demo's frame loop: camera along the road, GL scene pass, sun visibility, the temporal
// filter (smoothed coverage, edge fade, exposure), the sprite flare, tone mapping. With
// `raycast` the last three run on the CPU over the read-back frame; with a GPU method they run
// on the GPU from the method's 1x1 coverage texture, and the CPU reads only the finished frame.
#include <chrono>
#include <optional>

#include "demo/DemoWorld.h"
#include "flarekit/Demo.h"
#include "flarekit/GpuFlare.h"
#include "flarekit/GpuVisibility.h"
#include "flarekit/Render.h"
#include "flarekit/Tonemap.h"
#include "flarekit/Visibility.h"
#include "scene/CameraMath.h"

namespace flarekit {

namespace {
using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }
}  // namespace

Scene demoScene(int width, int height, double t) {
    Scene s = demo::buildWorld(width, height);
    s.camera = demo::cameraAt(t);
    return s;
}

//! The GPU half of a frame for the GPU methods: nothing crosses to the CPU but the image.
struct GpuFlarePath {
    std::unique_ptr<GpuVisibility> method;
    GpuTemporalFilter filter;
    GpuSpriteFlare flare;
    GpuTonemap tonemap;
};

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
    std::optional<GpuFlarePath> gpu;  // set for GPU methods
    int nextFrame = 0;

    Status drawFlareOnCpu(DemoFrame& frame, int index, double dt);
    Status drawFlareOnGpu(DemoFrame& frame, double dt);
};

DemoAnimation::DemoAnimation(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
DemoAnimation::~DemoAnimation() = default;
DemoAnimation::DemoAnimation(DemoAnimation&&) noexcept = default;
DemoAnimation& DemoAnimation::operator=(DemoAnimation&&) noexcept = default;

int DemoAnimation::frameCount() const { return m->settings.frames; }
std::size_t DemoAnimation::primitiveCount() const { return m->caster.primitiveCount(); }

Status validateDemoSettings(const DemoSettings& settings) {
    if (settings.width < 16 || settings.height < 16 || settings.width > 16384 || settings.height > 16384) {
        return invalidInput("size: expected each side in [16, 16384], got " + std::to_string(settings.width) + "x" +
                            std::to_string(settings.height));
    }
    if (Status s = validateParams<DemoSettings>(settings, kDemoParams, ""); !s) return s;
    if (settings.method != "raycast" && !isGpuVisibilityMethod(settings.method)) {
        return invalidInput("method: expected one of " + visibilityMethodList() + ", got '" + settings.method + "'");
    }
    if (settings.conditionalRender && settings.method != "query") {
        return invalidInput("conditional-render: needs --method query (the only method with an occlusion query), got '" +
                            settings.method + "'");
    }
    return validateTemporalParams(settings.temporal);
}

Result<DemoAnimation> DemoAnimation::create(const DemoSettings& settings, const Preset& preset) {
    if (Status s = validateDemoSettings(settings); !s) return s.error();
    Scene world = demo::buildWorld(settings.width, settings.height);
    auto renderer = SceneRenderer::create(world, {settings.msaaSamples});
    if (!renderer) return renderer.error();
    std::optional<GpuFlarePath> gpu;
    if (settings.method != "raycast") {
        auto method = createGpuVisibility(settings.method, world);
        if (!method) return method.error();
        auto filter = GpuTemporalFilter::create(settings.temporal);
        if (!filter) return filter.error();
        auto flare = GpuSpriteFlare::create(preset, settings.height);
        if (!flare) return flare.error();
        auto tonemap = GpuTonemap::create(settings.width, settings.height);
        if (!tonemap) return tonemap.error();
        gpu.emplace(GpuFlarePath{std::move(*method), std::move(*filter), std::move(*flare), std::move(*tonemap)});
    }
    auto impl = std::make_unique<Impl>(settings, preset, std::move(world), std::move(*renderer));
    impl->gpu = std::move(gpu);
    return DemoAnimation(std::move(impl));
}

Result<DemoFrame> DemoAnimation::next() {
    Impl& d = *m;
    if (d.nextFrame >= d.settings.frames) return invalidInput("demo: no frame after the last");
    const int index = d.nextFrame++;
    // Frame i shows time i x dt with dt = duration / frames: 240 frames are 30 fps for 8 s.
    const double t = double(index) / d.settings.frames;
    const double dt = kDemoDurationSeconds / d.settings.frames;

    Scene& view = d.view;  // camera, sun and size: what draw() and measure() read each frame
    view.camera = demo::cameraAt(t);
    DemoFrame frame;
    frame.time = t * kDemoDurationSeconds;

    frame.sunInFront = projectDirection(view, view.sun.direction, frame.sunPixel);
    const auto t0 = Clock::now();
    if (Status s = d.renderer.draw(view); !s) return s.error();
    frame.renderMs = ms(t0, Clock::now());
    const double dtNow = index == 0 ? 0.0 : dt;
    if (Status s = d.gpu ? d.drawFlareOnGpu(frame, dtNow) : d.drawFlareOnCpu(frame, index, dtNow); !s) return s.error();
    return frame;
}

// raycast: rays on the CPU, then filter, flare and tone map over the read-back frame.
Status DemoAnimation::Impl::drawFlareOnCpu(DemoFrame& frame, int index, double dt) {
    const auto t0 = Clock::now();
    auto image = renderer.readColor();
    if (!image) return image.error();
    frame.renderMs += ms(t0, Clock::now());
    const auto t1 = Clock::now();
    RaycastOptions rays;
    rays.samplesPerSide = settings.raycastSamplesPerSide;
    rays.seed = std::uint64_t(index) + 1;  // fresh jitter each frame: noise averages out over time
    auto visibility = caster.measure(view, rays);
    if (!visibility) return visibility.error();
    const auto t2 = Clock::now();
    frame.rawCoverage = visibility->coverage;
    frame.inFrame = visibility->inFrame;
    frame.temporal = filter.update(frame.rawCoverage, frame.sunPixel, frame.sunInFront, settings.width,
                                   settings.height, dt);
    const FlaredFrame flare = addSunFlare(*image, view, preset, frame.temporal.flareWeight);
    frame.flareIntensity = flare.flareIntensity;
    tonemapAcesFitted(*image, float(frame.temporal.exposure));
    frame.image = std::move(*image);
    frame.visibilityMs = ms(t1, t2);
    frame.flareMs = ms(t2, Clock::now());
    return Ok{};
}

// A GPU method: measure, filter, flare and tone map are all GPU passes chained through 1x1
// textures; the only read is the finished frame (and, after it, the few values for the CSV).
Status DemoAnimation::Impl::drawFlareOnGpu(DemoFrame& frame, double dt) {
    GpuFlarePath& g = *gpu;
    const auto t0 = Clock::now();
    if (Status s = g.method->measure(view, renderer); !s) return s;
    const auto t1 = Clock::now();
    if (Status s = g.filter.update(g.method->coverageTexture(), frame.sunPixel, frame.sunInFront, settings.width,
                                   settings.height, dt);
        !s) {
        return s;
    }
    auto flare = g.flare.draw(renderer, view, g.filter.stateTexture(), int(GpuStateChannel::FlareWeight),
                              settings.conditionalRender ? g.method->conditionalRenderQuery() : 0);
    if (!flare) return flare.error();
    if (Status s = g.tonemap.apply(renderer, g.filter.stateTexture(), int(GpuStateChannel::Exposure)); !s) return s;
    auto image = g.tonemap.read();  // the frame's output: the one wait in the loop
    if (!image) return image.error();
    frame.image = std::move(*image);
    const auto t2 = Clock::now();
    // Reporting only; the GPU has finished the frame, so these reads cost a texel each.
    auto consumed = g.filter.readConsumedCoverage();
    if (!consumed) return consumed.error();
    frame.rawCoverage = *consumed;
    frame.inFrame = sunInFrameFraction(view);
    auto state = g.filter.readState();
    if (!state) return state.error();
    frame.temporal = *state;
    frame.flareIntensity = float(frame.temporal.flareWeight) * flare->flareIntensity;
    frame.visibilityMs = ms(t0, t1);
    frame.flareMs = ms(t1, t2);
    return Ok{};
}

}  // namespace flarekit
