// SPDX-License-Identifier: Apache-2.0
// The frame pipeline (flarekit/gl/FramePipeline.h): one wiring of scene -> coverage -> temporal
// filter -> flare -> tone map, with a CPU and a GPU variant of the last three.
#include "flarekit/gl/FramePipeline.h"

#include <chrono>
#include <optional>

#include "flarekit/Tonemap.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/GpuFlare.h"
#include "scene/CameraMath.h"

namespace flarekit {

namespace {
using Clock = std::chrono::steady_clock;
//! A still's "temporal state": no smoothing, no edge fade, no adaptation; the flare weighs the raw
//! coverage.
TemporalState stillState(double coverage) {
    return {coverage, 1, 1, coverage};
}
double ms(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}
}  // namespace

//! The GPU half of a frame for the GPU methods: nothing crosses to the CPU but the image.
struct GpuFlarePath {
    std::unique_ptr<GpuVisibility> method;
    GpuTemporalFilter filter;
    GpuSpriteFlare flare;
    GpuTonemap tonemap;
};

struct FramePipeline::Impl {
    Impl(FramePipelineSettings s, Preset p, const Scene& world, SceneRenderer r)
        : settings(std::move(s)),
          preset(std::move(p)),
          renderer(std::move(r)),
          caster(world),
          filter(settings.temporalParams) {}
    FramePipelineSettings settings;
    Preset preset;
    SceneRenderer renderer;
    RaycastCaster caster;
    TemporalFilter filter;
    std::optional<GpuFlarePath> gpu;  // set for GPU methods

    Status cpuHalf(const Scene& view, PipelineFrame& frame, double dt, std::uint64_t raySeed);
    Status gpuHalf(const Scene& view, PipelineFrame& frame, double dt);
};

Result<FramePipeline> FramePipeline::create(const Scene& world, const Preset& preset,
                                            const FramePipelineSettings& settings) {
    if (Status s = checkVisibilityMethod(settings.method); !s) return s.error();
    if (Status s = validateTemporalParams(settings.temporalParams); !s) return s.error();
    if (Status s = validateScene(world); !s) return invalidInput("scene: " + s.error().message);
    auto renderer = SceneRenderer::create(world, settings.render);
    if (!renderer) return renderer.error();
    auto impl = std::make_unique<Impl>(settings, preset, world, std::move(*renderer));
    if (settings.method != "raycast") {
        auto method = createGpuVisibility(settings.method, world, settings.methodOptions);
        if (!method) return method.error();
        auto filter = GpuTemporalFilter::create(settings.temporalParams);
        if (!filter) return filter.error();
        auto flare = GpuSpriteFlare::create(preset, world.height);
        if (!flare) return flare.error();
        auto tonemap = GpuTonemap::create(world.width, world.height);
        if (!tonemap) return tonemap.error();
        impl->gpu.emplace(GpuFlarePath{std::move(*method), std::move(*filter), std::move(*flare),
                                       std::move(*tonemap)});
    }
    return FramePipeline(std::move(impl));
}

FramePipeline::FramePipeline(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
FramePipeline::~FramePipeline() = default;
FramePipeline::FramePipeline(FramePipeline&&) noexcept = default;
FramePipeline& FramePipeline::operator=(FramePipeline&&) noexcept = default;

std::size_t FramePipeline::primitiveCount() const {
    return m->caster.primitiveCount();
}

Result<PipelineFrame> FramePipeline::run(const Scene& view, double dt, std::uint64_t raySeed) {
    PipelineFrame frame;
    frame.sunInFront = projectDirection(view, view.sun.direction, frame.sunPixel);
    const auto t0 = Clock::now();
    if (Status s = m->renderer.draw(view); !s) return s.error();
    frame.renderMs = ms(t0, Clock::now());
    if (Status s = m->gpu ? m->gpuHalf(view, frame, dt) : m->cpuHalf(view, frame, dt, raySeed); !s)
        return s.error();
    return frame;
}

// raycast: rays on the CPU, then filter, flare and tone map over the read-back frame.
Status FramePipeline::Impl::cpuHalf(const Scene& view, PipelineFrame& frame, double dt,
                                    std::uint64_t raySeed) {
    const auto t0 = Clock::now();
    auto image = renderer.readColor();
    if (!image) return image.error();
    frame.renderMs += ms(t0, Clock::now());
    const auto t1 = Clock::now();
    RaycastOptions rays;
    rays.samplesPerSide = settings.raycastSamplesPerSide;
    rays.seed = raySeed;
    auto visibility = caster.measure(view, rays);
    if (!visibility) return visibility.error();
    const auto t2 = Clock::now();
    frame.rawCoverage = visibility->coverage;
    frame.inFrame = visibility->inFrame;
    if (settings.temporal) {
        frame.temporal = filter.update(frame.rawCoverage, frame.sunPixel, frame.sunInFront,
                                       view.width, view.height, dt);
    } else {
        frame.temporal = stillState(frame.rawCoverage);
    }
    if (settings.flare) {
        frame.flareIntensity =
            addSunFlare(*image, view, preset, frame.temporal.flareWeight).flareIntensity;
    }
    if (settings.toneMap) tonemapAcesFitted(*image, float(frame.temporal.exposure));
    frame.image = std::move(*image);
    frame.visibilityMs = ms(t1, t2);
    frame.flareMs = ms(t2, Clock::now());
    return Ok{};
}

// A GPU method: measure, filter, flare and tone map are GPU passes chained through 1x1
// textures; the only read is the finished frame (and, after it, the few values reported).
Status FramePipeline::Impl::gpuHalf(const Scene& view, PipelineFrame& frame, double dt) {
    GpuFlarePath& g = *gpu;
    const auto t0 = Clock::now();
    double stillCoverage = 0;
    if (settings.temporal) {
        if (Status s = g.method->measure(view, renderer); !s) return s;
    } else {
        // A still: late methods (pbo, query) need the frame drawn until their result is in.
        auto coverage = measureStillFrame(*g.method, renderer, view);
        if (!coverage) return coverage.error();
        stillCoverage = *coverage;
    }
    const auto t1 = Clock::now();
    // The flare's weight and the exposure: the filter's state, or (a still) the raw coverage.
    GpuChannel weight = g.method->coverage(), exposure{};
    if (settings.temporal) {
        if (Status s = g.filter.update(weight, frame.sunPixel, frame.sunInFront, view.width,
                                       view.height, dt);
            !s) {
            return s;
        }
        weight = g.filter.state(GpuStateChannel::FlareWeight);
        exposure = g.filter.state(GpuStateChannel::Exposure);
    }
    if (settings.flare) {
        auto flare =
            g.flare.draw(renderer, view, weight,
                         settings.conditionalRender ? g.method->conditionalRenderQuery() : 0);
        if (!flare) return flare.error();
        frame.flareIntensity = flare->flareIntensity;  // x the weight, below
    }
    Result<Image> image = internalError("unreached");
    if (settings.toneMap) {
        if (Status s = g.tonemap.apply(renderer, exposure); !s) return s;
        image = g.tonemap.read();  // the frame's output: the one wait in the loop
    } else {
        image = renderer.readColor();
    }
    if (!image) return image.error();
    frame.image = std::move(*image);
    const auto t2 = Clock::now();
    // Reporting only; the GPU has finished the frame, so these reads cost a texel each.
    frame.inFrame = sunInFrameFraction(view);
    if (settings.temporal) {
        auto consumed = g.filter.readConsumedCoverage();
        if (!consumed) return consumed.error();
        frame.rawCoverage = *consumed;
        auto state = g.filter.readState();
        if (!state) return state.error();
        frame.temporal = *state;
    } else {
        frame.rawCoverage = stillCoverage;
        frame.temporal = stillState(frame.rawCoverage);
    }
    frame.flareIntensity *= float(frame.temporal.flareWeight);
    if (settings.methodViews) frame.methodViews = g.method->views();
    frame.visibilityMs = ms(t0, t1);
    frame.flareMs = ms(t1, t2);
    return Ok{};
}

}  // namespace flarekit
