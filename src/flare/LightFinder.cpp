// SPDX-License-Identifier: Apache-2.0
// `--light auto`: find the light sources of an image and measure their flux. Luminance is
// computed once; each candidate is grown from its own peak by a flood fill that visits only
// pixels near that peak, and judged against the ring of pixels around it.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/DiscMask.h"
#include "core/LuminanceSample.h"
#include "core/Parallel.h"
#include "core/RadixSort.h"
#include "flare/LightRegion.h"
#include "flare/LightRings.h"
#include "flare/LuminanceMap.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"

namespace flarekit {

namespace {

using namespace lightfinder;

//! Regions examined at most: far more lights than any flare shows, few enough that the ring
//! sampling (kRingSamples each) stays a small fraction of one pass over a 1080p frame.
constexpr std::size_t kMaxCandidates = 256;
//! A light's region (its pixels within 90% of its peak) is mostly its core at white: past the
//! clipped disc a lens's glare falls steeply, so the band between white and 90% is a thin ring
//! (blender-data's suns rendered to 8-bit: 67-84% at white). A sunlit white object is a broad
//! plateau just under white with clipped spots in it (a dandelion's seeds: 10%).
constexpr float kMinWhiteShare = 0.4f;
//! Display-referred shape limits: a light is a compact blob (most of a sun's clipped glare lies
//! within 1.25 radii of its centre, even cut by branches; a cloud or a lit edge spreads out), no
//! smaller than 0.4% of the frame height in radius (a 4-pixel glint on a boat is not a light at
//! 720p) and no more than a quarter of the frame (a low sun's clipped glare in a phone photo can be
//! a tenth of it; beyond a quarter it is sky).
constexpr float kMinCompactness = 0.6f;
constexpr float kMinRadiusOfHeight = 0.004f;
constexpr float kMaxFrameShare = 0.25f;
//! Where the clip hides the peak, a light still shows its glare: the rim just outside the
//! clipped region keeps at least this share of its brightness (a sun's sky, a lamp's bloom:
//! 0.5-0.9), while a white object ends at a hard edge (a petal, a shirt, a wall: 0.1-0.35).
constexpr float kMinHaloShare = 0.45f;
//! Regions up to this share of the frame keep their surroundings out of later candidates.
constexpr float kSuppressFrameShare = 0.04f;
//! A light whose flare would be this faint (ghosts at 2% of the preset's look) is not flared.
//! In HDR data a region that passed the contrast check (1000x the frame's median) is a light
//! whatever its size, so the floor is halved there: blender-data's low, hazy sunset sun (2,090
//! over two pixels, its aureole a few times the sky) measures 0.012.
constexpr float kMinFlareScale = 0.02f, kMinHdrFlareScale = 0.01f;

//! A float's bits: for non-negative values they order as the values do.
std::uint32_t bitsOf(float l) {
    return std::bit_cast<std::uint32_t>(l);
}

//! The seed's pixel: keys hold the inverted index (ties of luminance in raster order).
std::size_t seedOf(std::uint64_t key) {
    return std::size_t(0xFFFFFFFFu - std::uint32_t(key & 0xFFFFFFFFu));
}

//! The seeds' keys, one per pixel at or above `minLuminance`, in raster order: the luminance's
//! bits (monotonic for non-negative floats) over the inverted index. Rows are counted, then
//! filled, in parallel.
SortKeys seedKeys(const LuminanceMap& m, float minLuminance) {
    static_assert(kMaxImagePixels <= 0xFFFFFFFFu, "a pixel index fits the key's low 32 bits");
    std::vector<std::size_t> rowStart(std::size_t(m.h) + 1, 0);
    parallelFor(0, m.h, 32, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* row = &m.lum[std::size_t(y) * std::size_t(m.w)];
            rowStart[std::size_t(y) + 1] = std::size_t(
                std::count_if(row, row + m.w, [&](float l) { return !(l < minLuminance); }));
        }
    });
    for (std::size_t y = 0; y < std::size_t(m.h); ++y) rowStart[y + 1] += rowStart[y];
    SortKeys keys(rowStart.back());  // every key is written below: not cleared first
    parallelFor(0, m.h, 32, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            std::size_t k = rowStart[std::size_t(y)];
            for (std::size_t i = std::size_t(y) * std::size_t(m.w);
                 i < std::size_t(y + 1) * std::size_t(m.w); ++i) {
                if (m.lum[i] < minLuminance) continue;
                keys[k++] =
                    (std::uint64_t(bitsOf(m.lum[i])) << 32) | (0xFFFFFFFFu - std::uint32_t(i));
            }
        }
    });
    return keys;
}

//! A hazy sun: haze spreads most of its light into a wide aureole and leaves a dim core (a
//! peak of 44 at 76x the frame's median). Its aureole keeps falling over at least
//! kHazyAureoleRings rings (out to about 30 core radii) and carries at least
//! kHazyAureoleShare of its flux, where a lit window or a patch of sky ends within a few rings;
//! such a candidate needs only kMinClippedContrast times the median, like a clipped one, and
//! still its prominence and compactness.
//! It must also carry a sun's flux (a flare scale of kMinHazyFlareScale): a dim window in a
//! night frame sits in the falling glow of the lamps around it and measures an aureole too,
//! but at a flare scale of 0.015-0.019 (blender-data's night).
constexpr int kHazyAureoleRings = 10;
constexpr double kHazyAureoleShare = 2.0 / 3.0;
constexpr float kMinHazyFlareScale = 0.05f;

bool isHazySun(const LightCandidate& c) {
    return c.aureoleRings >= kHazyAureoleRings && c.aureoleFlux >= kHazyAureoleShare * c.flux &&
           c.compactness >= kMinCompactness && c.flareScale >= kMinHazyFlareScale;
}

//! Judges a measured candidate; sets accepted and verdict.
void judge(LightCandidate& c, const LightSearchOptions& o, const LuminanceMap& m,
           bool displayReferred, float frameKey) {
    c.flareScale = flareScaleForFlux(c.flux, m.h);
    // Each check passed counts, so a frame with no light names the candidate that came closest.
    c.checksPassed = 0;
    auto reject = [&](std::string why) { c.verdict = std::move(why); };
    auto passed = [&] { ++c.checksPassed; };
    if (displayReferred && !c.clipped)
        return reject("not clipped (a light in 8/16-bit data reaches white in all three channels)");
    passed();
    const float keyContrast = c.flatTopPixels >= kFlatTopPixels ? clipContrast(c, m)
                              : isHazySun(c)                    ? kMinClippedContrast
                                                                : kMinKeyContrast;
    if (!displayReferred && c.peak < keyContrast * frameKey)
        return reject(format("only %.1fx the frame's median luminance (a light is %.0fx)",
                             c.peak / frameKey, keyContrast));
    passed();
    if (c.prominence < o.minProminence)
        return reject(
            format("only %.2fx its surroundings (needs %.2fx)", c.prominence, o.minProminence));
    passed();
    if (displayReferred) {
        if (c.radius < kMinRadiusOfHeight * float(m.h))
            return reject(format("too small: radius %.1f px (needs %.1f)", c.radius,
                                 kMinRadiusOfHeight * float(m.h)));
        passed();
        // The core at white must itself be of a light's size: a soft bright region with a few
        // clipped pixels in it (a glint on water, a lamp's reflection in snow) is not one.
        if (whiteShare(c) < kMinWhiteShare)
            return reject(format("mostly under white: %.0f%% of it at white (a light: %.0f%%)",
                                 100.0 * double(whiteShare(c)), 100.0 * kMinWhiteShare));
        passed();
        const float whiteRadius = std::sqrt(float(c.whitePixels) / std::numbers::pi_v<float>);
        if (whiteRadius < kMinRadiusOfHeight * float(m.h))
            return reject(format("its core at white is too small: radius %.1f px (needs %.1f)",
                                 whiteRadius, kMinRadiusOfHeight * float(m.h)));
        passed();
        if (double(c.pixels) > kMaxFrameShare * double(m.w) * double(m.h))
            return reject(format("too large: %.1f%% of the frame (at most %.0f%%)",
                                 100.0 * double(c.pixels) / (double(m.w) * double(m.h)),
                                 100.0 * kMaxFrameShare));
        passed();
        if (c.compactness < kMinCompactness)
            return reject(format("not compact: %.2f of it near its centre (needs %.2f)",
                                 c.compactness, kMinCompactness));
        passed();
        if (c.halo < kMinHaloShare)
            return reject(format("a hard edge, no glare: its rim keeps %.2f of it (needs %.2f)",
                                 c.halo, kMinHaloShare));
        passed();
    }
    if (!displayReferred && c.flatTopPixels >= kFlatTopPixels) {
        // A plateau is judged as a clipped 8-bit light is: a compact disc, not a clipped sky.
        if (double(c.pixels) > kMaxFrameShare * double(m.w) * double(m.h) ||
            c.compactness < kMinCompactness)
            return reject(
                format("a clipped plateau, not a light's disc: compactness %.2f, "
                       "%.1f%% of the frame",
                       c.compactness, 100.0 * double(c.pixels) / (double(m.w) * double(m.h))));
    }
    passed();
    const float minScale = displayReferred ? kMinFlareScale : kMinHdrFlareScale;
    if (c.flareScale < minScale)
        return reject(format("too faint: flare scale %.4f (needs %.2f)", c.flareScale, minScale));
    passed();
    c.accepted = true;
    c.verdict = "light";
}

//! A bright patch near a far brighter light is that light's glare (the fringe of a sun broken
//! up by branches), not a light of its own: within kGlareReachOfHeight frame heights of a
//! light kGlareContrast times brighter. Lamps in a row are of one brightness and all stay.
constexpr float kGlareReachOfHeight = 0.15f, kGlareContrast = 10.f;

void rejectGlareFragments(std::vector<LightCandidate>& candidates, float height) {
    for (LightCandidate& c : candidates) {
        if (!c.accepted) continue;
        for (const LightCandidate& light : candidates) {
            if (!light.accepted || light.peak < kGlareContrast * c.peak) continue;
            const float dx = c.position.x - light.position.x, dy = c.position.y - light.position.y;
            if (std::hypot(dx, dy) > kGlareReachOfHeight * height) continue;
            c.accepted = false;
            c.verdict =
                format("glare of the light at %.0f,%.0f", light.position.x, light.position.y);
            break;
        }
    }
}

//! Candidate `b` folded into `a`: flux and pixels summed, the flux-weighted centre, the larger
//! peak, the radius of the summed area, a verdict naming how many regions it joins.
void mergeInto(LightCandidate& a, const LightCandidate& b, int height) {
    const double fa = a.flux, fb = b.flux, f = fa + fb;
    if (f > 0)
        a.position = {float((a.position.x * fa + b.position.x * fb) / f),
                      float((a.position.y * fa + b.position.y * fb) / f)};
    a.meanLuminance = float(
        (double(a.meanLuminance) * double(a.pixels) + double(b.meanLuminance) * double(b.pixels)) /
        double(a.pixels + b.pixels));
    a.pixels += b.pixels;
    a.flux = f;
    a.peak = std::max(a.peak, b.peak);
    a.radius = std::sqrt(float(a.pixels) / std::numbers::pi_v<float>);
    a.flareScale = flareScaleForFlux(a.flux, height);
}

//! Accepted candidates of one physical light (kMergeRadii) become one, in the place of the
//! brightest; the others stay in the candidate list, no longer accepted, saying which light
//! took them.
void mergeNearbyLights(std::vector<LightCandidate>& candidates, int height) {
    std::vector<std::size_t> lights;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (candidates[i].accepted) lights.push_back(i);
    // Union-find over the accepted ones: a strip's spots chain into one light.
    std::vector<std::size_t> parent(lights.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto root = [&](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (std::size_t i = 0; i < lights.size(); ++i)
        for (std::size_t j = i + 1; j < lights.size(); ++j) {
            if (!ofOneLight(candidates[lights[i]], candidates[lights[j]])) continue;
            const std::size_t ri = root(i), rj = root(j);
            parent[std::max(ri, rj)] = std::min(ri, rj);  // the root stays the brightest
        }
    // Candidates are in seed order, brightest peak first, so a group's root is its brightest.
    std::vector<int> joined(lights.size(), 1);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::size_t r = root(i);
        if (r == i) continue;
        LightCandidate& into = candidates[lights[r]];
        LightCandidate& part = candidates[lights[i]];
        mergeInto(into, part, height);
        ++joined[r];
        part.accepted = false;
        part.verdict = format("part of the light at %.0f,%.0f", into.position.x, into.position.y);
    }
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (joined[i] > 1)
            candidates[lights[i]].verdict = format("light (%.0f regions of one light)", joined[i]);
}

//! The search over the seeds, brightest first: each seed not yet taken grows a candidate, which
//! is measured, judged and (with its halo) taken out of the search.
struct CandidateSearch {
    const LuminanceMap& m;
    const Image& image;
    const LightSearchOptions& options;
    LightSearch& result;
    std::vector<std::uint8_t> seen;  //!< taken: in a candidate's region or halo
    std::vector<PixelAt> stack, members;

    bool full() const { return result.candidates.size() >= kMaxCandidates; }
    bool taken(std::size_t seed) const { return seen[seed] != 0; }

    void examine(std::size_t seed) {
        if (taken(seed)) return;  // by a light found since the seed's group was sorted
        const float peak = m.lum[seed];
        const float threshold = regionThreshold(peak, options.nearPeak, result.displayReferred);
        LightCandidate c = growRegion(m, &image, seed, threshold, options.clippedGain,
                                      result.displayReferred, seen, stack, members);
        const float ring = ringMean(m, c.position, std::max(2.f * c.radius, c.radius + 2.f),
                                    std::max(4.f * c.radius, c.radius + 6.f));
        c.prominence = ring > 0.f ? c.meanLuminance / ring : 1e6f;
        const float rim = ringMean(m, c.position, c.radius + 1.f, 1.5f * c.radius + 2.f);
        c.halo = rim >= 0.f ? rim / c.meanLuminance : 0.f;
        if (!result.displayReferred)
            addSceneReferredFlux(c, m, result.frameKey, options.clippedGain);
        judge(c, options, m, result.displayReferred, result.frameKey);
        // Small regions keep their halo (the disc of twice their radius) out of the search; a
        // huge one already holds it.
        if (double(c.pixels) <= kSuppressFrameShare * double(m.w) * double(m.h))
            markDisc(seen.data(), m.w, m.h, c.position.x, c.position.y,
                     std::max(2.f * c.radius, c.radius + 2.f));
        result.candidates.push_back(std::move(c));
    }
};

}  // namespace

std::size_t closestCandidate(std::span<const LightCandidate> candidates) {
    // The first of the most checks passed, then the most flux (max_element keeps the first).
    const auto best = std::max_element(
        candidates.begin(), candidates.end(), [](const LightCandidate& a, const LightCandidate& b) {
            return a.checksPassed != b.checksPassed ? a.checksPassed < b.checksPassed
                                                    : a.flux < b.flux;
        });
    return std::size_t(best - candidates.begin());
}

float flareScaleForFlux(double flux, int height) {
    if (height <= 0 || !(flux > 0)) return 0.f;
    return float(flux / (double(height) * double(height)) / kReferenceFlux);
}

LightSearch findLights(const Image& image, const LightSearchOptions& options) {
    if (image.empty()) {
        LightSearch none;
        none.whyNone = "empty image";
        return none;
    }
    return findLightsIn(luminanceMap(image), image, options);
}

LightSearch lightfinder::findLightsIn(const LuminanceMap& m, const Image& image,
                                      const LightSearchOptions& options) {
    LightSearch result;
    result.peak = m.lum[m.peakIndex];
    result.peakAt = {float(m.peakIndex % std::size_t(m.w)) + 0.5f,
                     float(m.peakIndex / std::size_t(m.w)) + 0.5f};
    result.displayReferred = isDisplayReferred(m.brightestChannel);
    result.frameKey = medianLuminance(m);
    if (!(result.peak >= options.minLuminance)) {
        result.whyNone = format("peak luminance %.3f is below --light-threshold %.3f", result.peak,
                                options.minLuminance);
        return result;
    }

    // Seeds: every pixel above the threshold, brightest first (ties in raster order). The keys,
    // made in raster order, are grouped by luminance in one counting pass; a group is sorted
    // only when the search reaches it, and only its seeds not yet taken by an earlier light's
    // region or halo (on a photograph most of them are by then).
    HighBuckets seeds =
        bucketByHigh32Descending(seedKeys(m, options.minLuminance),
                                 bitsOf(std::max(options.minLuminance, 0.f)), bitsOf(result.peak));
    CandidateSearch search{m,  image, options, result, std::vector<std::uint8_t>(m.lum.size(), 0),
                           {}, {}};
    for (std::size_t b = 0; b < seeds.count() && !search.full(); ++b) {
        const auto first = seeds.keys.begin() + std::ptrdiff_t(seeds.begin[b]);
        const auto last =
            std::remove_if(first, seeds.keys.begin() + std::ptrdiff_t(seeds.begin[b + 1]),
                           [&](std::uint64_t key) { return search.taken(seedOf(key)); });
        sortDescending(seeds.keys, seeds.begin[b], std::size_t(last - seeds.keys.begin()));
        for (auto key = first; key != last && !search.full(); ++key) search.examine(seedOf(*key));
    }

    rejectGlareFragments(result.candidates, float(m.h));
    mergeNearbyLights(result.candidates, m.h);
    for (const LightCandidate& c : result.candidates)
        if (c.accepted) result.lights.push_back(c);
    std::stable_sort(
        result.lights.begin(), result.lights.end(),
        [](const LightCandidate& a, const LightCandidate& b) { return a.flux > b.flux; });
    if (result.lights.size() > std::size_t(options.maxLights))
        result.lights.resize(std::size_t(options.maxLights));
    if (result.lights.empty()) {
        const LightCandidate* best = &result.candidates[closestCandidate(result.candidates)];
        result.whyNone = "no convincing light: the closest candidate, at " +
                         format("%.0f,%.0f", best->position.x, best->position.y) +
                         format(" (peak %.4g), is ", double(best->peak)) + best->verdict;
    }
    return result;
}

}  // namespace flarekit
