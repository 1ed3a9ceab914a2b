// SPDX-License-Identifier: Apache-2.0
// GPU sun visibility, one interface for every method of the seed articles: after the scene
// pass, measure() starts the method on that frame; its newest result sits in a 1x1 R32F
// texture on the GPU (what flare shaders read: no CPU read-back in the frame loop), and
// latestCoverage() fetches it for reporting. A GL context must be current.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/GpuChannel.h"
#include "flarekit/gl/Render.h"

namespace flarekit {

struct GpuVisibilityOptions {
    //! texture-mask sampling: "square" (the seed: a 16x16 sun map, one point per texel, 256),
    //! "circle" (its improvement: an 18x18 map, points only on the texels inside the disc) or
    //! "bilinear" (16x16, 64 points each averaging a 2x2 block through bilinear filtering).
    std::string textureMaskVariant = "circle";
    int pboRing = 3;  //!< pbo: buffers in flight; results arrive up to ring - 1 frames late
};

//! One of a method's working textures, read back: the seeds' diagnostic views (GPG2 texture
//! masking's sun map and intensity map, the Burnout chain's mask, 14x14 grid and downsamples).
struct MethodView {
    std::string name;  //!< what it is and its size, e.g. "sun map 16x16"
    Image image;       //!< its texels top row first, RGBA as the shaders see them (unorm in [0, 1])
};

class GpuVisibility {
  public:
    virtual ~GpuVisibility() = default;
    virtual std::string name() const = 0;
    //! Starts measuring the frame `renderer` has just drawn for `view` (camera and sun).
    virtual Status measure(const Scene& view, const SceneRenderer& renderer) = 0;
    //! The newest available coverage: red of a 1x1 R32F texture (texture 0 until the first).
    virtual GpuChannel coverage() const = 0;
    //! Collects finished work without waiting (pbo, query) and returns the newest coverage, or
    //! nullopt if none has arrived yet. Reading it may wait for the GPU (one texel).
    virtual std::optional<double> latestCoverage() = 0;
    //! Frames between a measure() and its result becoming the newest (0: same frame).
    virtual int latencyFrames() const = 0;
    //! measure() calls since the one whose result is the newest now (0: the last one). A late
    //! method's newest result ages while its next results are in flight; measureStillFrame
    //! asks this to know a result is of its view and not of one measured before.
    virtual int resultAge() const { return latencyFrames(); }
    //! A GL query of the newest measure() that counts the sun's visible samples, for
    //! glBeginConditionalRender (`query` only; 0 for the other methods): drawing gated by it
    //! is skipped by the GPU when the sun was hidden, with no CPU involvement.
    virtual unsigned conditionalRenderQuery() const { return 0; }
    //! The working textures of the newest measure() (empty for a method that keeps none, or
    //! when that measure() drew none: a sun out of frame or culled). Reading them waits for the
    //! GPU: for diagnostic panels and tests, never a frame loop.
    virtual std::vector<MethodView> views() const { return {}; }
};

//! One still frame measured to completion: draws `view` and measures it, again and again until
//! a result of this view has arrived (late methods, pbo and query, need more than one frame;
//! a method reused from another view may hold that view's result until then),
//! at most maxFrames times. `frames` receives the frames it took minus one (the latency seen).
Result<double> measureStillFrame(GpuVisibility& method, SceneRenderer& renderer, const Scene& view,
                                 int maxFrames = 16, int* frames = nullptr);

//! A method over the objects `renderer` has uploaded (texture-mask re-draws them from the sun's
//! own camera, so it needs `world` for culling).
Result<std::unique_ptr<GpuVisibility>> createGpuVisibility(
    const std::string& method, const Scene& world, const GpuVisibilityOptions& options = {});

//! How `flarekit visibility` measures a scene on the GPU.
struct SceneVisibilityOptions {
    std::string source;  //!< the scene file, for messages
    std::string method;  //!< a GPU method (gpuVisibilityMethods)
    GpuVisibilityOptions methodOptions;
    RenderOptions render;        //!< the scene pass (shadows are off: visibility reads depth only)
    std::string backend = "gl";  //!< "vulkan": compute through the Vulkan backend
};

//! Every light of `scene` measured by a GPU method in its own headless context. The seeds'
//! one-light methods measure one light at a time: each light stands in as the frame's sun
//! (lightAsSun: a point light as the disc its sphere subtends, seen where the depth reaches its
//! near side), the frame is drawn and measured until its result arrives; `latencyFrames` gets
//! the most extra frames a late method (pbo, query) took. compute and texture-mask on a scene
//! with more than the sun measure every light at once through the engine API's batched pass
//! (the coverage the embedding API gives an application).
Result<VisibilityResult> gpuSceneVisibility(const Scene& scene,
                                            const SceneVisibilityOptions& options,
                                            int* latencyFrames = nullptr);

}  // namespace flarekit
