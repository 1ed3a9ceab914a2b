// SPDX-License-Identifier: Apache-2.0
// `--light X,Y`: a hand-placed light measured as `--light auto` measures the lights it finds.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/LuminanceSample.h"
#include "core/Smoothstep.h"
#include "flare/LightRegion.h"
#include "flarekit/Flare.h"

namespace flarekit {

using namespace lightfinder;

namespace {
//! How far from a hand-placed point the light's peak is looked for: 2% of the frame height
//! (21 px at 1080p) covers a click beside a sun's core, not the next lamp along a street.
constexpr float kPlacedReachOfHeight = 0.02f;
constexpr float kMinPlacedReachPx = 4.f;
//! A placed light's region stops 10% of the frame height from the point: the finder refuses
//! regions larger than a light (a clipped sky, an even wall), a placed light has no verdict,
//! so its region is bounded instead; a low sun's clipped glare in a phone photo, the largest
//! light the finder takes, stays within it.
constexpr float kPlacedRegionOfHeight = 0.1f;

}  // namespace

LightCandidate measureLightAt(const Image& image, Point at, const LightSearchOptions& options) {
    LightCandidate c;
    c.position = at;
    c.accepted = true;
    c.verdict = "placed";
    if (image.empty()) return c;
    // Outside the frame a light is measured as inside (the pixels of its reach that are in the
    // frame: a sun straddling the edge), its flare then faded out over that reach, so a track
    // crossing the edge changes by little between neighbouring positions, never from nothing
    // to the preset's full strength.
    const float reach = std::max(kMinPlacedReachPx, kPlacedReachOfHeight * float(image.height()));
    const float outX = std::max({0.f, -at.x, at.x - float(image.width())}),
                outY = std::max({0.f, -at.y, at.y - float(image.height())});
    const float outside = std::hypot(outX, outY);
    if (!(outside < reach)) {
        c.verdict = "placed outside the frame beyond its measuring reach: no flux";
        return c;
    }
    const float edgeFade = 1.f - smoothstep01(outside / reach);
    const LuminanceMap m = luminanceMap(image);
    const bool displayReferred = isDisplayReferred(m.brightestChannel);
    std::size_t seed = 0;
    float peak = -1.f;
    const int x0 = std::max(0, int(std::floor(at.x - reach))),
              x1 = std::min(m.w - 1, int(std::floor(at.x + reach))),
              y0 = std::max(0, int(std::floor(at.y - reach))),
              y1 = std::min(m.h - 1, int(std::floor(at.y + reach)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float dx = float(x) + 0.5f - at.x, dy = float(y) + 0.5f - at.y;
            const std::size_t i = std::size_t(y) * std::size_t(m.w) + std::size_t(x);
            if (dx * dx + dy * dy <= reach * reach && m.lum[i] > peak) peak = m.lum[i], seed = i;
        }
    if (!(peak > 0.f)) return c;
    // The same region and flux as CandidateSearch::examine.
    const float threshold = regionThreshold(peak, options.nearPeak, displayReferred);
    std::vector<std::uint8_t> seen(m.lum.size(), 0);
    std::vector<PixelAt> stack, members;
    LightCandidate measured =
        growRegion(m, &image, seed, threshold, options.clippedGain, displayReferred, seen, stack,
                   members, std::max(reach, kPlacedRegionOfHeight * float(m.h)), at);
    if (!displayReferred)
        addSceneReferredFlux(measured, m, medianLuminance(m), options.clippedGain);
    measured.accepted = true;
    measured.verdict = outside > 0 ? "placed outside the frame, measured at its edge" : "placed";
    // One flare per physical light, placed or found: a point on one spot of a strip light or
    // one pane of a window takes the flux of the light the finder makes of all of them (the
    // accepted light this region would merge with, by the merge rule), as `--light auto` draws
    // it. The flare stays where it was placed.
    LightSearchOptions all = options;
    all.maxLights = std::numeric_limits<int>::max();
    for (const LightCandidate& light : findLightsIn(m, image, all).lights)
        if (light.flux > measured.flux && ofOneLight(light, measured)) {
            measured.flux = light.flux;
            measured.verdict +=
                format(", on the light at %.0f,%.0f", light.position.x, light.position.y) + " (" +
                light.verdict + ")";
        }
    measured.flareScale = flareScaleForFlux(measured.flux, m.h) * edgeFade;
    return measured;
}

}  // namespace flarekit
