// Streaks and rays (Tanczos 1999): thin antialiased spikes radiating from the centre. Streaks are
// "evenly spaced" (4 streaks are 90 degrees apart) and full length; rays are "lines of random
// length". A spike is the half-strip along its angle, `thickness` wide, whose brightness fades
// as (1 - along/length)^falloff; across it, coverage is box-filtered over one pixel.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/FastMath.h"
#include "core/Random.h"
#include "elements/Coverage.h"
#include "elements/ElementKernel.h"

namespace flarekit {

namespace {
constexpr float kTwoPi = 2.f * std::numbers::pi_v<float>;
//! Ray brightness is uniform in [kRayMinWeight, 1]: varied, never invisible.
constexpr float kRayMinWeight = 0.4f;
}  // namespace

std::vector<Spike> makeSpikes(const ElementParams& p) {
    std::vector<Spike> spikes;
    spikes.reserve(std::size_t(p.count));
    if (p.type == ElementType::Streaks) {
        for (int i = 0; i < p.count; ++i)
            spikes.push_back({kTwoPi * float(i) / float(p.count), 1.f, 1.f});
    } else {
        SplitMix64 rng(p.seed);
        for (int i = 0; i < p.count; ++i) {
            const float angle = kTwoPi * rng.nextFloat();
            const float length = p.minLength + (1.f - p.minLength) * rng.nextFloat();
            const float weight = kRayMinWeight + (1.f - kRayMinWeight) * rng.nextFloat();
            spikes.push_back({std::min(angle, std::nextafter(kTwoPi, 0.f)), length, weight});
        }
    }
    std::sort(spikes.begin(), spikes.end(),
              [](const Spike& a, const Spike& b) { return a.angle < b.angle; });
    return spikes;
}

Rgba shadeSpikes(const ElementKernel& k, float x, float y) {
    const float d = std::sqrt(x * x + y * y);
    float theta = fastAtan2(y, x);
    if (theta < 0.f) theta += kTwoPi;
    const float halfWidth = 0.5f * k.params.thickness;

    // Only spikes within this angle can reach the pixel: perp = d*sin(delta) <= maxHalfWidth.
    const std::size_t n = k.spikes.size();
    const float window =
        d > k.maxHalfWidth ? asinUpperBound(k.maxHalfWidth / d) : 0.5f * std::numbers::pi_v<float>;
    float lo = theta - window;
    if (lo < 0.f) lo += kTwoPi;
    const auto first = std::lower_bound(k.spikes.begin(), k.spikes.end(), lo,
                                        [](const Spike& s, float a) { return s.angle < a; });
    const std::size_t start = std::size_t(first - k.spikes.begin());

    float sum = 0.f;
    for (std::size_t j = 0; j < n; ++j) {
        const Spike& s = k.spikes[(start + j) % n];
        float offset = s.angle - lo;
        if (offset < 0.f) offset += kTwoPi;
        if (offset > 2.f * window) break;
        const float delta = theta - s.angle;
        const float along = d * std::cos(delta);
        if (along <= 0.f || along >= s.length) continue;
        const float perp = d * std::sin(delta);
        const float cover = coverage::interval(perp, -halfWidth, halfWidth, k.pixel);
        if (cover > 0.f)
            sum += s.weight * cover * std::pow(1.f - along / s.length, k.params.falloff);
    }
    return gradient(k, std::min(d, 1.f), sum);
}

}  // namespace flarekit
