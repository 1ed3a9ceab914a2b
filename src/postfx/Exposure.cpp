// The frame's white and the chain's parameters relative to it: one preset gives the same flare
// on an HDR frame exposed two stops under or over, and on the 8-bit photo of it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "flarekit/Color.h"
#include "flarekit/PostFxParams.h"

namespace flarekit {

namespace {
//! Middle grey's share of white (the 18% grey card): a frame's median maps to it.
constexpr float kMiddleGrey = 0.18f;
//! Median from a strided sample of at most ~64k pixels: exact enough for an exposure, cheap.
constexpr std::size_t kMedianSamples = 65536;
//! The white is kept in [1/1024, 1e4]: a black frame still has one, a blown-out one is capped.
constexpr float kMinWhite = 1.f / 1024.f, kMaxWhite = 1e4f;
}  // namespace

float frameWhite(const Image& image) {
    if (image.empty()) return 1.f;
    const std::size_t n = image.pixelCount();
    const std::size_t stride = std::max<std::size_t>(1, n / kMedianSamples);
    std::vector<float> sample;
    float peak = 0.f;
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = image.data() + 4 * i;
        peak = std::max({peak, p[0], p[1], p[2]});
        if (i % stride == 0) {
            const float l = luminance(p[0], p[1], p[2]);
            sample.push_back(std::isfinite(l) ? l : 0.f);
        }
    }
    if (!(peak > 1.f + 1e-3f)) return 1.f;  // display-referred: the display is the exposure
    std::nth_element(sample.begin(), sample.begin() + std::ptrdiff_t(sample.size() / 2),
                     sample.end());
    return std::clamp(sample[sample.size() / 2] / kMiddleGrey, kMinWhite, kMaxWhite);
}

PostFxParams relativeToExposure(const PostFxParams& params, const Image& input) {
    if (!params.bright.exposureRelative) return params;
    const float white = frameWhite(input);
    PostFxParams p = params;
    p.bright.threshold *= white;
    p.bright.knee *= white;
    p.bright.ceiling *= white;
    for (GhostParams& g : p.ghosts) g.threshold *= white;
    p.halo.threshold *= white;
    p.streaks.threshold *= white;
    return p;
}

}  // namespace flarekit
