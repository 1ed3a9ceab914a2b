// SPDX-License-Identifier: Apache-2.0
// Streaks and rays (Tanczos 1999): thin antialiased spikes radiating from the centre. Streaks are
// "evenly spaced" (4 streaks are 90 degrees apart) and full length; rays are "lines of random
// length". A spike is the half-strip along its angle, `thickness` wide, whose brightness fades
// as (1 - along/length)^falloff. Across it the profile is a thin Gaussian core (`thickness` is
// its full width at half maximum) with a soft exponential wing, like the streaks of a real
// lens's diffraction spikes or of Blender's Glare node, never the hard-edged bar of a box.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/FastMath.h"
#include "core/Random.h"
#include "elements/ElementKernel.h"

namespace flarekit {

namespace {
constexpr float kTwoPi = 2.f * std::numbers::pi_v<float>;
//! Ray brightness is uniform in [kRayMinWeight, 1]: varied, never invisible.
constexpr float kRayMinWeight = 0.4f;
//! A Gaussian's full width at half maximum is 2 sqrt(2 ln 2) = 2.3548 sigma.
constexpr float kFwhmPerSigma = 2.3548f;
//! Narrowest core, in pixels. A Gaussian sampled at pixel centres steps most steeply on its
//! flank, about peak * exp(-1/2) / sigma per pixel near u = sigma; for no step above a quarter
//! of the peak (a smooth line, not a stair, at any resolution) the core needs sigma >= 2.5 px
//! (largest step 0.24 of the core's peak: exp(-2^2/12.5) - exp(-3^2/12.5)). Thinner spikes are
//! widened to it with their peak lowered, so they keep their energy.
constexpr float kMinCoreSigmaPx = 2.5f;
//! Share of the peak in the wing, and the wing's 1/e width in thicknesses: a faint glow a few
//! line widths wide around the crisp core.
constexpr float kWingShare = 0.15f;
constexpr float kWingScalePerThickness = 1.f;
//! The profile is cut where it is below 1/512 of its peak (under one 8-bit level at peak 1):
//! 3.5 sigma for the core, ln(512 * kWingShare) = 4.34 scales for the wing.
constexpr float kCoreCutSigmas = 3.5f, kWingCutScales = 4.34f;
//! Peak that gives the profile the energy of a box `thickness` wide (so a preset's streaks
//! carry the same light as before the profile existed): the core integrates to
//! (1 - share) sqrt(2 pi) sigma, the wing to 2 share scale.
constexpr float kProfilePeak = 1.f / ((1.f - kWingShare) * 2.5066283f / kFwhmPerSigma +
                                      2.f * kWingShare * kWingScalePerThickness);
//! Spikes at most for which testing each one beats finding the few near the pixel's angle (an
//! atan2, an arcsine bound and a binary search): a preset's streaks (4 to 8), not its rays.
constexpr std::size_t kSpikesTestedDirectly = 12;

//! Whether spike s can light the pixel at (x, y): the tests the summing loop makes.
inline bool reaches(const ElementKernel& k, const Spike& s, float x, float y) {
    const float along = x * s.cosAngle + y * s.sinAngle;
    if (along <= 0.f || along >= s.length) return false;
    return std::abs(y * s.cosAngle - x * s.sinAngle) < k.maxHalfWidth;
}

}  // namespace

SpikeProfile makeSpikeProfile(float thickness, float pixel) {
    SpikeProfile p;
    const float sigma = thickness / kFwhmPerSigma;
    p.coreSigma = std::max(sigma, kMinCoreSigmaPx * pixel);
    p.coreAmp = kProfilePeak * (1.f - kWingShare) * sigma / p.coreSigma;
    const float scale = kWingScalePerThickness * thickness;
    p.wingScale = std::max(scale, kMinCoreSigmaPx * pixel);
    p.wingAmp = kProfilePeak * kWingShare * scale / p.wingScale;
    return p;
}

float spikeSupport(const SpikeProfile& p) {
    return std::max(kCoreCutSigmas * p.coreSigma, kWingCutScales * p.wingScale);
}

float spikeAcross(const SpikeProfile& p, float u) {
    const float a = std::abs(u);
    const float c = a / p.coreSigma;
    return p.coreAmp * std::exp(-0.5f * c * c) + p.wingAmp * std::exp(-a / p.wingScale);
}

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
    for (Spike& s : spikes) s.cosAngle = std::cos(s.angle), s.sinAngle = std::sin(s.angle);
    return spikes;
}

Rgba shadeSpikes(const ElementKernel& k, float x, float y) {
    // Most of a few streaks' disc is dark: no spike reaches it, the sum below would stay 0 and
    // gradient() return nothing; said straight away, without the angle search.
    if (k.spikes.size() <= kSpikesTestedDirectly &&
        std::none_of(k.spikes.begin(), k.spikes.end(),
                     [&](const Spike& s) { return reaches(k, s, x, y); }))
        return {};
    const float d = std::sqrt(x * x + y * y);
    float theta = fastAtan2(y, x);
    if (theta < 0.f) theta += kTwoPi;

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
    // From the first spike past `lo` round the circle (wrapping at the end of the list).
    std::size_t index = start == n ? 0 : start;
    for (std::size_t j = 0; j < n; ++j, index = index + 1 == n ? 0 : index + 1) {
        const Spike& s = k.spikes[index];
        float offset = s.angle - lo;
        if (offset < 0.f) offset += kTwoPi;
        if (offset > 2.f * window) break;
        // d cos(theta - angle) and d sin(theta - angle), by the angle-difference identities.
        const float along = x * s.cosAngle + y * s.sinAngle;
        if (along <= 0.f || along >= s.length) continue;
        const float perp = y * s.cosAngle - x * s.sinAngle;
        if (std::abs(perp) >= k.maxHalfWidth) continue;
        sum += s.weight * spikeAcross(k.spikeProfile, perp) *
               std::pow(1.f - along / s.length, k.params.falloff);
    }
    return gradient(k, std::min(d, 1.f), sum);
}

}  // namespace flarekit
