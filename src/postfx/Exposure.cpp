// SPDX-License-Identifier: Apache-2.0
// The frame's white and the chain's parameters relative to it: one preset gives the same flare
// on an HDR frame exposed two stops under or over, and on the 8-bit photo of it.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "core/LuminanceSample.h"
#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"
#include "flarekit/PostFxParams.h"
#include "postfx/brightpass/BrightPass.h"

namespace flarekit {

namespace {
//! Middle grey's share of white (the 18% grey card): a frame's median maps to it.
constexpr float kMiddleGrey = 0.18f;
//! Metering clips highlights at this many times the median (3 stops): a bright sky counts, the
//! sun's few pixels do not. 8 keeps the default preset's flare on every blender-data HDRI with
//! a sun under 15% of the frame changed (a backlit forest: 11%) and still visible on a clear
//! sunrise (4%); 16 dims the sunrise to 2%, 4 lets the forest reach 14%.
constexpr float kMeterClip = 8.f;
//! The white is kept in [1/1024, 1e4]: a black frame still has one, a blown-out one is capped.
constexpr float kMinWhite = 1.f / 1024.f, kMaxWhite = 1e4f;

//! Whether any colour channel of the frame passes display white: a scan on every core that
//! each band stops at the first such pixel.
bool anyChannelPastDisplayWhite(const Image& image) {
    std::atomic<bool> found{false};
    parallelFor(0, image.height(), 64, [&](int y0, int y1) {
        for (int y = y0; y < y1 && !found.load(std::memory_order_relaxed); ++y) {
            const float* p = image.row(y);
            float peak = 0.f;
            for (int x = 0; x < image.width(); ++x, p += 4)
                peak = std::max({peak, p[0], p[1], p[2]});
            if (!isDisplayReferred(peak)) found.store(true, std::memory_order_relaxed);
        }
    });
    return found.load();
}

}  // namespace

float frameWhite(const Image& image) {
    if (image.empty()) return 1.f;
    const std::size_t n = image.pixelCount();
    const std::size_t stride = luminanceSampleStride(n);
    std::vector<float> sample;
    sample.reserve(n / stride + 1);
    float peak = 0.f;
    for (std::size_t i = 0; i < n; i += stride) {
        const float* p = image.data() + 4 * i;
        peak = std::max({peak, p[0], p[1], p[2]});
        const float l = luminance(p[0], p[1], p[2]);
        // Light is never negative: a resize's ringing beside a sun (-3,600) would otherwise
        // pull the metered mean below 0 and every threshold with it.
        sample.push_back(std::isfinite(l) ? std::max(l, 0.f) : 0.f);
    }
    // The sample settles most HDR frames; only one that shows nothing past white is scanned
    // whole, since a few sun pixels between the samples still make it scene-referred.
    if (isDisplayReferred(peak) && !anyChannelPastDisplayWhite(image)) return 1.f;
    const float median = medianOf(sample);
    // Average metering, as a camera's meter reads the scene: the mean luminance with highlights
    // clipped at kMeterClip x the median, so a sun of 30,000 does not set the exposure but a
    // sky that fills a third of the frame does (a backlit forest, a courtyard's bright arch).
    double sum = 0;
    for (float l : sample) sum += std::min(l, kMeterClip * median);
    const float metered = float(sum / double(sample.size()));
    return std::clamp(metered / kMiddleGrey, kMinWhite, kMaxWhite);
}

namespace {

//! The starburst's centres: the strongest lights `--light auto` would flare, else the
//! brightest pixel (an 8-bit photo's clipped highlight still has a place rays come from).
void placeStarCentres(StarburstParams& star, const Image& input) {
    LightSearchOptions options;
    options.maxLights = kMaxStarCentres;
    const LightSearch search = findLights(input, options);
    std::vector<Point> centres;
    for (const LightCandidate& light : search.lights) centres.push_back(light.position);
    if (centres.empty()) centres.push_back(search.peakAt);
    star.centreCount = int(centres.size());
    for (std::size_t i = 0; i < centres.size(); ++i) {
        // Pixels (y down from the top) to the passes' uv (y up from the bottom).
        star.centresUv[2 * i] = centres[i].x / float(input.width());
        star.centresUv[2 * i + 1] = 1.f - centres[i].y / float(input.height());
    }
}

}  // namespace

//! The bright pass's mean over the frame, from the metering's sample of pixels, each through
//! the pass's own curve (highlight compression, soft threshold) at the fitted thresholds.
float brightPassMean(const BrightParams& bright, const Image& input) {
    const std::size_t n = input.pixelCount();
    if (n == 0) return 0.f;
    const std::size_t stride = luminanceSampleStride(n);
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; i += stride, ++count) {
        const float* p = input.data() + 4 * i;
        const auto light = [](float v) { return std::isfinite(v) ? std::max(v, 0.f) : 0.f; };
        const postfx::F4 c = postfx::softThreshold(
            postfx::compressHighlights(postfx::F4{light(p[0]), light(p[1]), light(p[2]), 1.f},
                                       bright.ceiling),
            bright.threshold, bright.knee);
        sum += std::max({c[0], c[1], c[2]});
    }
    return float(sum / double(count));
}

PostFxParams fitToFrame(const PostFxParams& params, const Image& input) {
    PostFxParams p = params;
    if (p.starburst.intensity > 0.f && p.starburst.centre == StarCentre::Lights && !input.empty())
        placeStarCentres(p.starburst, input);
    if (!p.bright.exposureRelative) return p;
    const float white = p.bright.knownWhite > 0.f ? p.bright.knownWhite : frameWhite(input);
    p.bright.threshold *= white;
    p.bright.knee *= white;
    p.bright.ceiling *= white;
    for (GhostParams& g : p.ghosts) g.threshold *= white;
    p.halo.threshold *= white;
    p.streaks.threshold *= white;
    if (p.bright.areaReference > 0.f) {
        // Wide bright areas (a sunlit yard seen from an arcade, a sky over a third of the
        // frame) pass the threshold as a sun does, over thousands of times its pixels: their
        // bloom and ghosts would wash the whole frame. What the lens effects follow is capped
        // at a bright pass whose mean is area_reference.
        const float mean = brightPassMean(p.bright, input) / white;
        const float dim = mean > p.bright.areaReference ? p.bright.areaReference / mean : 1.f;
        p.bloom.intensity *= dim;
        p.flareIntensity *= dim;
    }
    return p;
}

}  // namespace flarekit
