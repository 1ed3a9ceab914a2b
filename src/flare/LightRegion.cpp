// SPDX-License-Identifier: Apache-2.0
// A light's region, grown from its peak by a flood fill that visits only pixels near that
// peak, and measured: flux, centre, shape, a capture clip's plateau, and in HDR data its
// aureole. The finder and a hand-placed light measure alike through it.
#include "flare/LightRegion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/LuminanceSample.h"
#include "flare/LightRings.h"
#include "flarekit/Color.h"

namespace flarekit::lightfinder {

namespace {
//! In HDR data a light's flux is summed over the pixels above this fraction of its peak: the
//! disc and its brightest fringe (a real sun falls from 31,000 to the sky's 50 within two
//! pixels), not the sky around it.
constexpr float kSourceFraction = 0.25f;
//! The frame's own clip: an HDR merge stores everything past its range at one value, which is
//! then the frame's brightest, so a plateau at the frame's peak is that clip whatever the
//! scene's key. It needs only kMinFrameClipContrast times the median: a sun clipped at 22 in a
//! daylight frame whose median is 0.5 (blender-data's city with its range cut at 22) stands 44x
//! over it, under the 50x asked of a plateau below the frame's peak. A clipped window or wall
//! is a plateau at the peak too, but it ends at a hard edge where a sun's glare goes on
//! falling around its clip: the plateau must have an aureole of kMinClipAureoleRings rings
//! (city's clipped sun: 8; a flat bright window: none).
constexpr float kMinFrameClipContrast = 20.f;
constexpr int kMinClipAureoleRings = 4;
}  // namespace

std::string format(const char* fmt, double a, double b) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, a, b);
    return buf;
}

//! The frame's median luminance from a strided sample of at most ~64k pixels (exact enough for
//! a contrast test, one cheap pass), floored at 1e-4 so a black frame still has a scale.
float medianLuminance(const LuminanceMap& m) {
    const std::size_t stride = luminanceSampleStride(m.lum.size());
    std::vector<float> sample;
    for (std::size_t i = 0; i < m.lum.size(); i += stride) sample.push_back(m.lum[i]);
    return std::max(medianOf(sample), 1e-4f);
}

//! The luminance a light's region is grown down to from its `peak`: its core (nearPeak of the
//! peak) in 8/16-bit data, where everything near the clip is the light; in HDR down to
//! kSourceFraction of it, but never below the core when that is under 1 (a dim peak's fringe).
float regionThreshold(float peak, float nearPeak, bool displayReferred) {
    const float core = nearPeak * peak;
    return displayReferred ? core : std::max(kSourceFraction * peak, std::min(core, 1.f));
}

//! Grows the region of `seed` over unseen pixels >= threshold (whose centres lie within
//! `maxRadius` px of `capCentre`) and measures it.
LightCandidate growRegion(const LuminanceMap& m, const Image* image, std::size_t seed,
                          float threshold, float clippedGain, bool displayReferred,
                          std::vector<std::uint8_t>& seen, std::vector<PixelAt>& stack,
                          std::vector<PixelAt>& members, float maxRadius, Point capCentre) {
    LightCandidate c;
    c.peak = m.lum[seed];
    double sum = 0, flux = 0, sx = 0, sy = 0;
    std::size_t whitePixels = 0;
    members.clear();
    seen[seed] = 1;
    const int seedX = int(seed % std::size_t(m.w)), seedY = int(seed / std::size_t(m.w));
    const float cap2 = maxRadius * maxRadius;
    stack.push_back({seedX, seedY});
    while (!stack.empty()) {
        const PixelAt p = stack.back();
        stack.pop_back();
        members.push_back(p);
        const int x = p.x, y = p.y;
        const std::size_t i = std::size_t(y) * std::size_t(m.w) + std::size_t(x);
        const double l = m.lum[i];
        sum += l;
        flux += displayReferred && m.clipped(i) ? double(clippedGain) : l;
        whitePixels += m.whiteCore(i) ? 1 : 0;
        sx += l * (x + 0.5);
        sy += l * (y + 0.5);
        auto visit = [&](int nx, int ny) {
            if (nx < 0 || ny < 0 || nx >= m.w || ny >= m.h) return;
            const float dx = float(nx) + 0.5f - capCentre.x, dy = float(ny) + 0.5f - capCentre.y;
            if (dx * dx + dy * dy > cap2) return;
            const std::size_t j = std::size_t(ny) * std::size_t(m.w) + std::size_t(nx);
            if (!seen[j] && m.lum[j] >= threshold) {
                seen[j] = 1;
                stack.push_back({nx, ny});
            }
        };
        visit(x - 1, y);
        visit(x + 1, y);
        visit(x, y - 1);
        visit(x, y + 1);
    }
    c.pixels = members.size();
    if (!displayReferred && image) {
        // A plateau at the top of the largest channel: the clip of an HDR merge (kFlatTopPixels).
        const auto brightest = [&](PixelAt p) {
            const Rgba& px = image->at(p.x, p.y);
            return std::max({px.r, px.g, px.b});
        };
        float top = 0.f;
        for (const PixelAt p : members) top = std::max(top, brightest(p));
        std::size_t plateau = 0, core = 0;
        for (const PixelAt p : members) {
            plateau += brightest(p) >= top * (1.f - kFlatTopTolerance);
            core += brightest(p) >= 0.5f * top;
        }
        if (float(plateau) >= kMinFlatTopShare * float(core)) c.flatTopPixels = plateau;
    }
    c.flux = flux;
    c.meanLuminance = float(sum / double(c.pixels));
    c.position = sum > 0 ? Point{float(sx / sum), float(sy / sum)}
                         : Point{float(seed % std::size_t(m.w)) + 0.5f,
                                 float(seed / std::size_t(m.w)) + 0.5f};
    c.radius = std::sqrt(float(c.pixels) / std::numbers::pi_v<float>);
    // Compactness: the share of its pixels within 1.25 radii of the centroid (1 for a disc or
    // a square, low for a cloud, a branch or a lit edge however large its bounding circle).
    const double reach2 = 1.5625 * double(c.radius) * double(c.radius) + 0.5;
    std::size_t inside = 0;
    for (const PixelAt p : members) {
        const double dx = double(p.x) + 0.5 - c.position.x;
        const double dy = double(p.y) + 0.5 - c.position.y;
        inside += dx * dx + dy * dy <= reach2;
    }
    c.compactness = float(double(inside) / double(c.pixels));
    c.clipped = displayReferred && m.whiteCore(seed);
    c.whitePixels = whitePixels;
    return c;
}

float clipContrast(const LightCandidate& c, const LuminanceMap& m) {
    const bool framesClip = c.peak >= (1.f - kFlatTopTolerance) * m.lum[m.peakIndex] &&
                            c.aureoleRings >= kMinClipAureoleRings;
    return framesClip ? kMinFrameClipContrast : kMinClippedContrast;
}

void addSceneReferredFlux(LightCandidate& c, const LuminanceMap& m, float frameKey,
                          float clippedGain) {
    const Aureole a = measureAureole(m, c.position, c.radius);
    c.aureoleFlux = a.flux, c.aureoleRings = a.rings;
    c.flux += a.flux;
    if (c.flatTopPixels >= kFlatTopPixels && c.peak < kMinKeyContrast * frameKey &&
        c.peak >= clipContrast(c, m) * frameKey)
        c.flux += double(c.flatTopPixels) * double(clippedGain - 1.f) * double(c.peak);
}

//! Two accepted candidates are one physical light when their centres lie within
//! kMergeRadii x (r_a + r_b) + kMergeSlackPx of each other: each candidate already keeps the
//! disc of twice its radius out of the search, so lights this close are the bright spots of
//! one strip, tube or window (a ceiling strip found as 4 blobs 5-7 px apart, a church window
//! twice 16 px apart), while lamps in a row stand many radii apart. The slack covers the
//! one- or two-pixel spots a thin strip breaks into.
namespace {
constexpr float kMergeRadii = 2.f, kMergeSlackPx = 4.f;

}  // namespace

bool ofOneLight(const LightCandidate& a, const LightCandidate& b) {
    const float reach = kMergeRadii * (a.radius + b.radius) + kMergeSlackPx;
    return std::hypot(a.position.x - b.position.x, a.position.y - b.position.y) <= reach;
}

}  // namespace flarekit::lightfinder
