// SPDX-License-Identifier: Apache-2.0
// One frame of a 3D scene with its sun flare, the chain both `flarekit demo` and `flarekit
// render` run: scene pass (GL) -> sun coverage (raycast on the CPU, or a GPU method) ->
// temporal filter -> sprite flare -> tone map. With `raycast` the filter, flare and tone map
// run on the CPU over the read-back frame; with a GPU method they run on the GPU from the
// method's 1x1 coverage texture and the CPU reads only the finished frame.
// A GL context must be current on the calling thread while a FramePipeline lives.
#pragma once

#include <memory>
#include <string>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Scene.h"
#include "flarekit/Temporal.h"
#include "flarekit/gl/GpuVisibility.h"
#include "flarekit/gl/Render.h"

namespace flarekit {

struct FramePipelineSettings {
    std::string method = "raycast";  //!< visibility method: raycast or a GPU method
    int raycastSamplesPerSide = 64;  //!< raycast strata per side
    RenderOptions render;            //!< MSAA, shadows
    GpuVisibilityOptions methodOptions;
    //! A sequence: coverage smoothed over time, edge fade and exposure adaptation (the
    //! TemporalFilter). A still (`render`): no filter, the flare weighs the raw coverage, late
    //! GPU methods are run until their result for this frame arrives.
    bool temporal = true;
    TemporalParams temporalParams;
    bool flare = true;    //!< false: the frame only
    bool toneMap = true;  //!< ACES fit x the (adapted) exposure; false: linear HDR out
    //! `query` only: the flare's draws are conditional on the sun's occlusion query.
    bool conditionalRender = false;
    //! Read the GPU method's working textures back after each frame (PipelineFrame::
    //! methodViews): a wait per frame, for diagnostic panels.
    bool methodViews = false;
};

struct PipelineFrame {
    Image image;             //!< tone-mapped linear [0, 1], or linear HDR without toneMap
    double rawCoverage = 0;  //!< the method's coverage this frame
    double inFrame = 0;      //!< fraction of the disc inside the frame
    TemporalState temporal;  //!< smoothed coverage, edge fade, exposure (a still: raw, 1, 1)
    bool sunInFront = false;
    Point sunPixel;
    float flareIntensity = 0;  //!< the flare's weight x the sun's brightness scale
    double renderMs = 0, visibilityMs = 0, flareMs = 0;
    //! With FramePipelineSettings::methodViews: the method's views of this frame (a late
    //! method's, pbo or query: none).
    std::vector<MethodView> methodViews;
};

class FramePipeline {
  public:
    //! Uploads `world`'s objects once; every frame reuses them.
    static Result<FramePipeline> create(const Scene& world, const Preset& preset,
                                        const FramePipelineSettings& settings);
    ~FramePipeline();
    FramePipeline(FramePipeline&&) noexcept;
    FramePipeline& operator=(FramePipeline&&) noexcept;

    //! One frame seen by `view` (its camera, sun and size; its objects are not read), `dt`
    //! seconds after the previous one (0 for the first). `raySeed` jitters raycast's strata.
    Result<PipelineFrame> run(const Scene& view, double dt, std::uint64_t raySeed = 1);
    std::size_t primitiveCount() const;  //!< objects uploaded (triangles, spheres, boxes)

  private:
    struct Impl;
    explicit FramePipeline(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit
