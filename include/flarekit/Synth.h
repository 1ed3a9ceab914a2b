// SPDX-License-Identifier: Apache-2.0
// The flare-data generator (`flarekit synth`, flarekit.synth in Python): seeded samples for
// training flare-removal networks, each a background, its lights, their flare pass by pass, a
// composite through an optional camera model and a label. Sample `index` of `seed` depends on
// nothing else (not the shard, the thread count or the order), so any sample can be made again
// from its two numbers.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"
#include "flarekit/Tonemap.h"
#include "flarekit/job/Job.h"

namespace flarekit {

//! The camera model's quantisations.
inline constexpr int kSynthBits[] = {0, 8, 16};

//! What the samples are drawn from (synth.json). Ranges are drawn uniformly unless said.
struct SynthConfig {
    int lightsMin = 1, lightsMax = 4;
    double offFrame = 0.2;               //!< share of lights placed outside the frame
    double offFrameMargin = 0.5;         //!< how far outside, in frame sizes
    double pointLights = 0.5;            //!< share of point lights (the rest: suns, at infinity)
    double depthMin = 1, depthMax = 20;  //!< point lights' distance, metres
    //! Peak radiance of a light, in display whites (log-uniform): 30, a street lamp's glowing
    //! globe, to 5,000, a sun behind haze; with the radii below the flux of the brightest is
    //! about the energy model's reference (docs/energy.md), so its flare is the presets' look.
    double intensityMin = 30, intensityMax = 5000;
    double radiusMin = 0.004, radiusMax = 0.012;  //!< a light's disc radius, of the frame height
    double spriteWeight = 1, postfxWeight = 1, lensWeight = 0.25;  //!< how often each flare kind
    double fNumberMax = 16;                    //!< lens flares: stopped down to up to this f-number
    int lensGhosts = 24;                       //!< lens flares: the brightest ghosts drawn
    double occluded = 0.3;                     //!< share of samples with occluders
    int occludersMax = 3;                      //!< up to this many discs and boxes in such a sample
    bool camera = false;                       //!< the camera model below on the composite (and gt)
    double exposureMin = -1, exposureMax = 1;  //!< stops
    bool autoExposure = true;  //!< before the exposure draw: the background's mean to 0.18
    ToneOperator tone = ToneOperator::None;
    double gammaMin = 1.8, gammaMax = 2.2;
    double shotNoise = 0.01, readNoise = 0.002;  //!< noise variance per unit signal, read sigma
    int bits = 8;         //!< quantisation of the camera model's output: 0 none, 8 or 16
    int jpegQuality = 0;  //!< > 0: the 8-bit output also through JPEG at this quality
    //! Backgrounds: images in this folder (8/16-bit decoded to linear; a random crop each);
    //! empty: a procedural sky and ground.
    std::string backgrounds;
};
inline constexpr Param<SynthConfig> kSynthParams[] = {
    // 64 lights: a night street's lamps; the flare's cost grows with each.
    param<&SynthConfig::lightsMin>("lights_min", 1, 64, "", "fewest lights in a sample"),
    param<&SynthConfig::lightsMax>("lights_max", 1, 64, "", "most lights in a sample"),
    param<&SynthConfig::offFrame>("off_frame", 0, 1, "", "share of lights outside the frame"),
    // 4 frame sizes: a light farther out than that puts no ghost in the frame.
    param<&SynthConfig::offFrameMargin>("off_frame_margin", 0, 4, "frames",
                                        "how far outside the frame such a light may be"),
    param<&SynthConfig::pointLights>("point_lights", 0, 1, "",
                                     "share of point lights at a random depth (1/r^2 dimmed)"),
    aboveMin(param<&SynthConfig::depthMin>("depth_min", 0, 1e6, "m", "nearest point light")),
    aboveMin(param<&SynthConfig::depthMax>("depth_max", 0, 1e6, "m", "farthest point light")),
    // 10^6 x white: a sun in display units, with a margin.
    aboveMin(param<&SynthConfig::intensityMin>("intensity_min", 0, 1e6, "x white",
                                               "dimmest light's peak radiance (log-uniform)")),
    aboveMin(param<&SynthConfig::intensityMax>("intensity_max", 0, 1e6, "x white",
                                               "brightest light's peak radiance")),
    aboveMin(param<&SynthConfig::radiusMin>("radius_min", 0, 0.5, "of the height",
                                            "smallest light disc radius")),
    aboveMin(param<&SynthConfig::radiusMax>("radius_max", 0, 0.5, "of the height",
                                            "largest light disc radius")),
    param<&SynthConfig::spriteWeight>("sprite", 0, 1e6, "", "weight of sprite-preset flares"),
    param<&SynthConfig::postfxWeight>("postfx", 0, 1e6, "", "weight of post-process flares"),
    param<&SynthConfig::lensWeight>("lens", 0, 1e6, "", "weight of lens-prescription flares"),
    // f/64: past it diffraction, not ghosts, shapes every flare.
    param<&SynthConfig::fNumberMax>("f_number_max", 1, 64, "",
                                    "lens flares: stopped down to at most this f-number"),
    param<&SynthConfig::lensGhosts>("lens_ghosts", 1, 4096, "",
                                    "lens flares: the brightest ghosts drawn"),
    param<&SynthConfig::occluded>("occluded", 0, 1, "", "share of samples with occluders"),
    param<&SynthConfig::occludersMax>("occluders_max", 1, 16, "",
                                      "most occluders (discs and boxes) in such a sample"),
    param<&SynthConfig::camera>("camera", 0, 1, "", "apply the camera model to composite and gt"),
    param<&SynthConfig::exposureMin>("exposure_min", -16, 16, "stops", "camera: exposure from"),
    param<&SynthConfig::exposureMax>("exposure_max", -16, 16, "stops", "camera: exposure to"),
    param<&SynthConfig::autoExposure>("auto_exposure", 0, 1, "",
                                      "camera: first scale the background's mean to 0.18"),
    choice<&SynthConfig::tone>("tone", kToneOperatorNames, "camera: tone curve before the gamma"),
    param<&SynthConfig::gammaMin>("gamma_min", 1, 3, "", "camera: encoding gamma from"),
    param<&SynthConfig::gammaMax>("gamma_max", 1, 3, "", "camera: encoding gamma to"),
    param<&SynthConfig::shotNoise>("shot_noise", 0, 1, "", "camera: shot noise variance per unit"),
    param<&SynthConfig::readNoise>("read_noise", 0, 1, "", "camera: read noise sigma"),
    oneOf<&SynthConfig::bits>("bits", std::span<const int>(kSynthBits), "bits",
                              "camera: quantisation, 0 (none), 8 or 16"),
    // libjpeg's quality scale; 0 leaves JPEG out (the Wu et al. pipeline compresses its pairs).
    param<&SynthConfig::jpegQuality>("jpeg_quality", 0, 100, "",
                                     "camera: 1-100 compresses the 8-bit output as JPEG at this "
                                     "quality (needs bits 8); 0: no JPEG"),
};

//! One sample: its layers (linear, unclamped, RGBA with alpha 1) and its label.
struct SynthSample {
    std::vector<std::pair<std::string, Image>> layers;  //!< background, light_source, flare, ...
    std::string label;                                  //!< one JSON line (no newline)
    double gamma = 2.2;                                 //!< the camera model's, else 2.2
    const Image* layer(const std::string& name) const;
};

//! The largest sample side (pixels) the generator takes.
inline constexpr int kMaxSynthSide = 16384;

//! synth.json as a config, every key through kSynthParams (plus "backgrounds", a folder): the
//! presets' messages ("synth.json: lights_max: expected ...").
Result<SynthConfig> parseSynthConfig(const std::string& jsonText, const std::string& source);
//! The ranges that need two keys (min <= max), and the backgrounds folder holding an image.
Status checkSynthConfig(const SynthConfig& config);
//! Every key of synth.json as a Markdown table (key, default, range, unit, help), as
//! docs/synth.md carries it (`flarekit synth --params`).
std::string synthParameterReference();
//! The config as JSON (every key), as the label and the output folder's manifest record it.
std::string synthConfigJson(const SynthConfig& config);

//! Sample `index` of `seed`, `width` x `height` pixels. `centred`: the flare7kpp layout's kind
//! (one light at the centre, over black, no occluder).
Result<SynthSample> synthSample(std::uint64_t index, std::uint64_t seed, int width, int height,
                                const SynthConfig& config, bool centred = false);

//! How a set of samples is written (`flarekit synth`).
enum class SynthFormat { Flare7kpp, Pairs, Exr };
inline constexpr std::string_view kSynthFormatNames[] = {"flare7kpp", "pairs", "exr"};

struct SynthRunOptions {
    std::uint64_t count = 0, seed = 0;
    int width = 512, height = 512;
    std::string out;
    SynthConfig config;
    int shardIndex = 0, shardCount = 1;  //!< this run makes shard I of K (0-based)
    SynthFormat format = SynthFormat::Exr;
    int depth = 8;        //!< pairs: 8 or 16-bit PNG
    bool resume = false;  //!< skip the samples already complete in `out`
};

struct SynthRunReport {
    std::uint64_t written = 0, skipped = 0;
    bool complete = false;  //!< every sample of the set is in `out` (labels.jsonl written)
};

//! Writes shard I/K of the set: each sample's files atomically, its label last (what marks it
//! complete), then labels.jsonl once the whole set is there. `out` holding another seed's or
//! config's samples is refused before any work.
Result<SynthRunReport> runSynthJob(const SynthRunOptions& options, const JobEvents& events = {});

}  // namespace flarekit
