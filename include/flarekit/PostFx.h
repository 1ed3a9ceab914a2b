// SPDX-License-Identifier: Apache-2.0
// Image-based (post-process) lens flare: the Killzone 2 / Kawase chain as Matt Pettineo (MJP)
// describes it in "More Post-Processing Tricks: Lens Flare" (2009), after Masaki Kawase's GDC
// 2003 talk, plus the pieces modern engines add.
// It needs no light position and no occlusion test: whatever is bright in the image flares.
//
//   input (linear HDR) -> bright pass (1/2 res) -> downsample chain -> bloom (1/4 res)
//   bloom -> ghosts, halo;  bright 1/4 -> streaks;  ghosts + halo -> chromatic, starburst
//   lens = (bloom + flare) x dirt  ->  input + lens  ->  optional tone map
//
// The CPU chain and the OpenGL chain run the same kernels (src/postfx/<pass>/) and agree to
// 1e-3 relative (tests/gl/PostFxParityTest.cpp). Parameters are described once, in
// flarekit/PostFxParams.h, which drives preset validation, CLI flags and docs/postfx.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "flarekit/Elements.h"
#include "flarekit/Image.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Result.h"

namespace flarekit {

//! What a run produces. Layers are at the working resolution (1/4 of the input), linear.
struct PostFxResult {
    Image final;    //!< input + lens, tone-mapped when params.tone.op != None; alpha kept
    Image bloom;    //!< bloom buffer x bloom.intensity (before dirt)
    Image ghosts;   //!< ghosts x flareIntensity, before chromatic aberration and starburst
    Image halo;     //!< halo x flareIntensity, likewise
    Image streaks;  //!< streaks x flareIntensity
    Image lens;     //!< everything added to the input, at the working resolution
};

struct PassTime {
    std::string pass;  //!< "bright", "downsample", "upsample", "ghosts", "halo", "streaks", "lens",
                       //!< "composite"; GL also "upload" and "read-back"
    double milliseconds = 0;  //!< CPU: wall time; GL: GPU time from a timer query
    double wallMilliseconds =
        0;  //!< wall time (GL: glFinish before and after; llvmpipe's timer queries are unreliable)
    double megapixels = 0;  //!< pixels the pass wrote, in millions
};

struct PostFxOptions {
    bool keepLayers = false;                 //!< fill bloom/ghosts/halo/streaks/lens
    std::vector<PassTime>* times = nullptr;  //!< when set, each pass is timed (GL: waits per pass)
    //! GL: every input value is exactly a half float (it was read from a half-float EXR), so the
    //! input goes up as halves into a half-float texture: half the bytes, the same values.
    bool halfInput = false;
    //! GL: the result is only kept as half floats (a half-float EXR), so it comes back as
    //! halves: half the bytes, the same file (each value rounded to half once either way).
    bool halfReadback = false;
    //! CPU: false stops at the lens buffer (keepLayers gives it; result.final is left as it
    //! was), for callers that add the flare to an image of their own, as the flare-data
    //! generator does: the full-resolution composite is then not drawn at all.
    bool composite = true;
};

//! The CPU chain (oneTBB threads, 4-wide SIMD per pixel), one run with fresh buffers.
Result<PostFxResult> postFxCpu(const Image& input, const PostFxParams& params,
                               const PostFxOptions& options = {});

//! The CPU chain keeping its intermediate buffers between runs of the same size (a video, a
//! benchmark): fresh multi-megabyte buffers cost a page fault per 4 KiB on every run.
class CpuPostFx {
  public:
    CpuPostFx();
    ~CpuPostFx();
    CpuPostFx(CpuPostFx&&) noexcept;
    CpuPostFx& operator=(CpuPostFx&&) noexcept;

    //! Writes the composite into `result.final` (reused when it already has the input's size)
    //! and, with options.keepLayers, the layers.
    Status run(const Image& input, const PostFxParams& params, PostFxResult& result,
               const PostFxOptions& options = {});
    //! As run, with the composite written over `image` itself rather than into `result.final`
    //! (left as it was): no second full-size buffer to allocate and fault in. The composite
    //! reads each input pixel only where it writes it, after every other pass has read it.
    Status runInPlace(Image& image, const PostFxParams& params, PostFxResult& result,
                      const PostFxOptions& options = {});

    struct Impl;

  private:
    std::unique_ptr<Impl> m;
};

//! The OpenGL chain. A GL 4.5 context must be current; textures are kept between runs of the
//! same size.
class GpuPostFx {
  public:
    static Result<GpuPostFx> create();
    ~GpuPostFx();
    GpuPostFx(GpuPostFx&&) noexcept;
    GpuPostFx& operator=(GpuPostFx&&) noexcept;

    //! Uploads, runs every pass and reads the result back.
    Result<PostFxResult> run(const Image& input, const PostFxParams& params,
                             const PostFxOptions& options = {});

    struct Impl;

  private:
    explicit GpuPostFx(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

//! The procedural dirt texture (values in [0, 1]) at the given size: a pure function of its params.
Image makeLensDirt(int width, int height, const DirtParams& params);

//! Bilinear resize (clamp-to-edge), the filter the composite upsamples the lens buffer with:
//! for viewing the 1/4-res layers at the input's size.
Image resizeBilinear(const Image& image, int width, int height);

}  // namespace flarekit
