// Image-based (post-process) lens flare: the Killzone 2 / Kawase chain of
// ../shared/seeds/killzone2-post-process-lens-flare.txt plus the pieces modern engines add.
// It needs no light position and no occlusion test: whatever is bright in the image flares.
//
//   input (linear HDR) -> bright pass (1/2 res) -> downsample chain -> bloom (1/4 res)
//   bloom -> ghosts, halo;  bright 1/4 -> streaks;  ghosts + halo -> chromatic, starburst
//   lens = (bloom + flare) x dirt  ->  input + lens  ->  optional tone map
//
// The CPU chain and the OpenGL chain run the same kernels (src/postfx/<pass>/) and agree to
// 1e-3 relative (tests/gl/PostFxParityTest.cpp). Parameters are described once, in
// src/postfx/PostFxParams.cpp, which drives preset validation and docs/postfx.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "flarekit/Elements.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"

namespace flarekit {

//! Soft-knee threshold on linear HDR (Unity's bloom prefilter curve).
struct BrightParams {
    float threshold = 1.0f;  //!< linear value where the flare starts [0, 1e4]
    float knee = 0.5f;       //!< width of the quadratic ease-in below the threshold [0, 1e4]
};

//! Downsample (13-tap dual filter) and progressive tent upsample into the 1/4-res bloom buffer.
struct BloomParams {
    float intensity = 0.05f;  //!< bloom added to the image [0, 100]
    int levels = 6;           //!< mip levels below full res, 1/2 ... 1/2^levels [2, 12]
    float spread = 1.0f;      //!< weight of each coarser level when upsampling [0, 1]
};

//! One ghost: the seed's LensFlarePS with its uniforms, plus the modern falloff.
struct GhostParams {
    Rgb tint{1.f, 1.f, 1.f};  //!< vTint of the seed [0, 100]
    float scale = 1.f;        //!< fTexScale: the ghost of a light at l appears at -l/scale [-16, 16], |scale| >= 0.05
    float blur = 0.f;         //!< fBlurScale: step between samples, in bloom-buffer texels / 2 (seed units) [0, 16]
    int samples = 12;         //!< NumSamples [1, 64]
    float threshold = 0.1f;   //!< fThreshold, subtracted from each bloom sample [0, 1e4]
    float falloff = 0.f;      //!< 0: none (seed); else weight (1 - |n| / sqrt 2)^falloff of the unblurred point n [0, 64]
    bool centered = false;    //!< false: the seed's sample offsets (+1, -1, -3, ...); true: symmetric about the point
    bool linearFilter = false;  //!< false: the seed's point sampler; true: bilinear (smoother magnified ghosts)
};

//! A ring around the screen centre (John Chapman's pseudo lens flare halo), aspect-correct.
struct HaloParams {
    float intensity = 0.f;            //!< 0 switches it off [0, 100]
    float radius = 0.5f;              //!< in half image heights [0, 4]
    float thickness = 0.1f;           //!< radial spread of the ring, half image heights [0, 2]
    float threshold = 0.1f;           //!< subtracted from each bloom sample [0, 1e4]
    float falloff = 5.f;              //!< (1 - |p| / sqrt 2)^falloff of the mid-radius sample point [0, 64]
    Rgb tint{1.f, 1.f, 1.f};          //!< [0, 100]
};

//! Anamorphic streaks: a long horizontal blur of the 1/4-res bright image.
struct StreakParams {
    float intensity = 0.f;          //!< 0 switches it off [0, 100]
    float length = 0.25f;           //!< half length, fraction of the image width [0, 2]
    float falloff = 4.f;            //!< exponential falloff along the streak, e^(-falloff |t|) [0, 64]
    float threshold = 0.f;          //!< subtracted from each sample [0, 1e4]
    Rgb tint{0.45f, 0.6f, 1.f};     //!< anamorphic lenses streak blue [0, 100]
};

//! Lateral chromatic aberration of the ghosts and halo: red and blue sampled radially apart.
struct ChromaticParams {
    float amount = 0.f;  //!< red at scale (1 + amount), blue at (1 - amount) about the centre [0, 0.5]
};

//! Procedural starburst modulation of ghosts and halo (angle about the screen centre).
struct StarburstParams {
    float intensity = 0.f;  //!< 0 off, 1 full modulation [0, 1]
    int spokes = 12;        //!< number of rays [2, 64]
    float width = 0.15f;    //!< ray half width, fraction of the spoke spacing [0.01, 1]
    std::uint32_t seed = 1; //!< per-ray random brightness [0, 2^31]
};

//! Procedural lens dirt: soft random specks and smudges that multiply bloom and flare.
struct DirtParams {
    float intensity = 0.f;   //!< 0 off; lens x (1 + intensity x dirt) [0, 100]
    int spots = 80;          //!< specks [0, 4096]
    std::uint32_t seed = 7;  //!< [0, 2^31]
};

enum class ToneOperator { None, Aces, Filmic };

struct ToneParams {
    ToneOperator op = ToneOperator::None;  //!< none (linear, clipped on 8-bit), aces (Narkowicz fit), filmic (Hable)
    float exposure = 1.f;                   //!< multiplies the image before the curve [0, 1000]
};

struct PostFxParams {
    std::string name;
    std::string description;
    BrightParams bright;
    BloomParams bloom;
    std::vector<GhostParams> ghosts;  //!< explicit ghosts first, then any "ghost_series" expanded
    HaloParams halo;
    StreakParams streaks;
    ChromaticParams chromatic;
    StarburstParams starburst;
    DirtParams dirt;
    ToneParams tone;
    float flareIntensity = 1.f;  //!< multiplies ghosts, halo and streaks [0, 1000]
};

//! Most ghosts one chain evaluates (a uniform array bound in the GL shader).
inline constexpr int kMaxGhosts = 32;

//! Parses and validates a preset; messages read "source: field: expected ..., got ...".
Result<PostFxParams> parsePostFxPreset(const std::string& jsonText, const std::string& source);
//! A shipped name (presets/postfx/NAME.json) or a path to a .json file.
Result<PostFxParams> loadPostFxPreset(const std::string& nameOrPath);
std::vector<std::string> shippedPostFxPresetNames();
//! Markdown table of every preset key (docs/postfx.md).
std::string postFxParameterReference();

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
    std::string pass;         //!< "bright", "downsample", "upsample", "ghosts", "halo", "streaks", "lens", "composite"
    double milliseconds = 0;  //!< CPU: wall time; GL: GPU time from a timer query
    double wallMilliseconds = 0;  //!< wall time (GL: glFinish before and after; llvmpipe's timer queries are unreliable)
    double megapixels = 0;    //!< pixels the pass wrote, in millions
};

struct PostFxOptions {
    bool keepLayers = false;             //!< fill bloom/ghosts/halo/streaks/lens
    std::vector<PassTime>* times = nullptr;  //!< when set, each pass is timed (GL: waits per pass)
};

//! The CPU chain (oneTBB threads, 4-wide SIMD per pixel), one run with fresh buffers.
Result<PostFxResult> postFxCpu(const Image& input, const PostFxParams& params, const PostFxOptions& options = {});

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
    Status run(const Image& input, const PostFxParams& params, PostFxResult& result, const PostFxOptions& options = {});

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
    Result<PostFxResult> run(const Image& input, const PostFxParams& params, const PostFxOptions& options = {});

    struct Impl;

private:
    explicit GpuPostFx(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

//! The procedural dirt texture (values in [0, 1]) at the given size: a pure function of its params.
Image makeLensDirt(int width, int height, const DirtParams& params);

}  // namespace flarekit

namespace flarekit {
//! Bilinear resize (clamp-to-edge), the filter the composite upsamples the lens buffer with:
//! for viewing the 1/4-res layers at the input's size.
Image resizeBilinear(const Image& image, int width, int height);
}  // namespace flarekit
