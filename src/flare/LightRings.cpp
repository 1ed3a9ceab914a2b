// SPDX-License-Identifier: Apache-2.0
#include "flare/LightRings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace flarekit::lightfinder {

namespace {

//! Calls `visit(luminance)` for each sample of the ring [inner, outer] around c that lies inside
//! the frame: kRingCircles circles of kRingAngles points, every other circle turned half a step.
template <class Visit>
void forRingSamples(const LuminanceMap& m, Point c, float inner, float outer, Visit&& visit) {
    for (int i = 0; i < kRingCircles; ++i) {
        const float r = inner + (outer - inner) * float(i) / float(kRingCircles - 1);
        for (int a = 0; a < kRingAngles; ++a) {
            const float angle = 2.f * std::numbers::pi_v<float> * (float(a) + 0.5f * float(i & 1)) /
                                float(kRingAngles);
            const int x = int(std::floor(c.x + r * std::cos(angle)));
            const int y = int(std::floor(c.y + r * std::sin(angle)));
            if (x < 0 || y < 0 || x >= m.w || y >= m.h) continue;
            visit(m.at(x, y));
        }
    }
}

}  // namespace

//! Mean luminance of the ring [inner, outer] around c (pixels inside the frame only; -1 if none).
float ringMean(const LuminanceMap& m, Point c, float inner, float outer) {
    double sum = 0;
    int n = 0;
    forRingSamples(m, c, inner, outer, [&](float l) { sum += l, ++n; });
    return n ? float(sum / n) : -1.f;
}

namespace {

//! The aureole is followed outward on rings from R + 1 px, each kAureoleStep times the last
//! radius plus a pixel (so a 1-pixel sun's glow of 100 px takes about 20 rings), no further
//! than kAureoleReachOfHeight of the frame height (a hazy sun's glow spans a tenth to a fifth of
//! a wide frame), while each ring's mean stays below kAureoleFalling of the ring inside it.
constexpr float kAureoleStep = 1.2f, kAureoleReachOfHeight = 0.25f, kAureoleFalling = 0.98f;

//! The upper quartile of the luminance on the ring [inner, outer] around c (pixels inside the
//! frame; -1 if none): the aureole's level at that radius where it is seen. A sun low over the
//! horizon has the sea or a skyline under half of every ring, and a glitter path on the water,
//! a branch or a mast crosses a few of its angles; all of them move a mean or a median, not the
//! brighter quarter of the ring.
float ringUpperQuartile(const LuminanceMap& m, Point c, float inner, float outer) {
    std::vector<float> samples;
    samples.reserve(kRingCircles * kRingAngles);
    forRingSamples(m, c, inner, outer, [&](float l) { samples.push_back(l); });
    if (samples.empty()) return -1.f;
    const auto quartile = samples.begin() + std::ptrdiff_t(samples.size() * 3 / 4);
    std::nth_element(samples.begin(), quartile, samples.end());
    return *quartile;
}

}  // namespace

//! The light a candidate's aureole carries: over the rings around it whose upper quartile keeps
//! falling, each ring's excess over the level where the falling stops (the local sky), times
//! its area.
Aureole measureAureole(const LuminanceMap& m, Point c, float radius) {
    std::vector<std::pair<float, float>> rings;  // (inner radius, mean) of each ring
    const float reach = kAureoleReachOfHeight * float(m.h);
    float inner = radius + 1.f, last = std::numeric_limits<float>::infinity();
    while (inner < reach) {
        const float outer = inner * kAureoleStep + 1.f;
        const float mean = ringUpperQuartile(m, c, inner, outer);
        if (mean < 0.f || !(mean < kAureoleFalling * last)) {
            rings.push_back({inner, std::max(mean, 0.f)});
            break;
        }
        rings.push_back({inner, mean});
        last = mean, inner = outer;
    }
    Aureole a;
    if (rings.size() < 2) return a;
    const float sky = rings.back().second;
    for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
        const double r0 = rings[k].first, r1 = rings[k + 1].first;
        a.flux +=
            std::max(0.0, double(rings[k].second - sky)) * std::numbers::pi * (r1 * r1 - r0 * r0);
    }
    a.rings = int(rings.size()) - 1;
    return a;
}

}  // namespace flarekit::lightfinder
