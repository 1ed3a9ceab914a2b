// SPDX-License-Identifier: Apache-2.0
// The flare's GPU half: the temporal filter, the sprite flare and the tone map run
// on the GPU and read the sun's coverage from the 1x1 texture a GpuVisibility method leaves,
// so a frame loop never waits for the GPU to learn how bright the flare is (GPG2 texture
// masking: "no CPU read-back"). Each reads the same as its CPU twin (TemporalFilter,
// renderFlare, tonemapAcesFitted); tests hold them to it. A GL context must be current.
#pragma once

#include <memory>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Temporal.h"
#include "flarekit/gl/GpuChannel.h"
#include "flarekit/gl/Render.h"

namespace flarekit {

//! Channels of GpuTemporalFilter::stateTexture(), the layout of TemporalState.
enum class GpuStateChannel { Coverage = 0, EdgeFade = 1, Exposure = 2, FlareWeight = 3 };

//! TemporalFilter on the GPU: a fragment pass over ping-pong 1x1 RGBA32F textures reads the
//! previous state and the method's raw coverage texture and writes the new state.
class GpuTemporalFilter {
  public:
    static Result<GpuTemporalFilter> create(const TemporalParams& params = {});
    ~GpuTemporalFilter();
    GpuTemporalFilter(GpuTemporalFilter&&) noexcept;
    GpuTemporalFilter& operator=(GpuTemporalFilter&&) noexcept;

    //! One frame, as TemporalFilter::update, with the raw coverage in `rawCoverage` (a
    //! GpuVisibility's coverage()). Nothing is read back.
    Status update(GpuChannel rawCoverage, Point sunPixel, bool sunInFront, int width, int height,
                  double dtSeconds);
    //! One value of the newest state (an RGBA32F 1x1 texture, channels as GpuStateChannel).
    GpuChannel state(GpuStateChannel channel) const;
    //! Reads the state back (waits for the GPU): for reports and tests only.
    Result<TemporalState> readState() const;
    //! Reads back the raw coverage the last update consumed (NaN/Inf as 0, clamped to [0, 1]):
    //! with a late method (pbo, query) an earlier frame's result. For reports and tests only.
    Result<double> readConsumedCoverage() const;

  private:
    struct Impl;
    explicit GpuTemporalFilter(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

//! The sprite flare drawn with GL into a SceneRenderer's HDR colour target: one textured quad
//! per element (the element rendered once on the CPU, Tanczos's sprite textures), placed on
//! the flare vector like renderFlare and composited with the element's blend mode. The vertex
//! shader takes the flare's weight from a 1x1 texture, so the CPU never learns it.
class GpuSpriteFlare {
  public:
    //! Element textures for frames `height` pixels tall (sizes are fractions of the height).
    static Result<GpuSpriteFlare> create(const Preset& preset, int height);
    ~GpuSpriteFlare();
    GpuSpriteFlare(GpuSpriteFlare&&) noexcept;
    GpuSpriteFlare& operator=(GpuSpriteFlare&&) noexcept;

    //! Adds the flare for `view`'s sun to `target`'s colour: every element scaled by
    //! sunFlareScale(scene) x `weight` (a method's coverage, or the temporal state's
    //! FlareWeight). Returns where the sun projects
    //! and the brightness scale (flareIntensity = that scale; the weight stays on the GPU).
    //! With `conditionQuery` (GpuVisibility::conditionalRenderQuery()) the draws are made
    //! conditional on it (glBeginConditionalRender, GL_QUERY_NO_WAIT: the GPU skips them when
    //! no sample of the sun passed, and never makes the CPU wait).
    Result<FlaredFrame> draw(const SceneRenderer& target, const Scene& view, GpuChannel weight,
                             unsigned conditionQuery = 0) const;
    std::size_t elementCount() const;  //!< elements with a texture (radius >= half a pixel)

  private:
    struct Impl;
    explicit GpuSpriteFlare(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

//! tonemapAcesFitted on the GPU: `target`'s HDR colour x `exposure` (none: exposure 1), ACES
//! fitted, into a display target read back as
//! linear [0, 1] RGBA (the read waits for the GPU: it is the frame's output).
class GpuTonemap {
  public:
    static Result<GpuTonemap> create(int width, int height);
    ~GpuTonemap();
    GpuTonemap(GpuTonemap&&) noexcept;
    GpuTonemap& operator=(GpuTonemap&&) noexcept;

    Status apply(const SceneRenderer& source, GpuChannel exposure = {});
    //! The last apply() result, top row first.
    Result<Image> read() const;

  private:
    struct Impl;
    explicit GpuTonemap(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit
