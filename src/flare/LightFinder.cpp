// SPDX-License-Identifier: Apache-2.0
// `--light auto`: find the light sources of an image and measure their flux. Luminance is
// computed once; each candidate is grown from its own peak by a flood fill that visits only
// pixels near that peak, and judged against the ring of pixels around it.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "core/DiscMask.h"
#include "core/LuminanceSample.h"
#include "core/Parallel.h"
#include "core/RadixSort.h"
#include "core/Smoothstep.h"
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
//! In HDR data a light's flux is summed over the pixels above this fraction of its peak: the
//! disc and its brightest fringe (a real sun falls from 31,000 to the sky's 50 within two
//! pixels), not the sky around it.
constexpr float kSourceFraction = 0.25f;
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
//! In scene-referred (HDR) data a light stands far above the frame's exposure: its peak is at
//! least this many times the frame's median luminance. Real suns and lamps are 10^3-10^6 x
//! (blender-data HDRIs: suns of 950-33,000 over medians of 0.1-0.25, 8,000-300,000 x; night
//! lamps of 4,000 over 0.013); a bright sky through an arch, a sun's broken fringe or a lit
//! cloud 5-250 x.
constexpr float kMinKeyContrast = 1000.f;
//! A light whose flare would be this faint (ghosts at 2% of the preset's look) is not flared.
//! In HDR data a region that passed the contrast check (1000x the frame's median) is a light
//! whatever its size, so the floor is halved there: blender-data's low, hazy sunset sun (2,090
//! over two pixels, its aureole a few times the sky) measures 0.012.
constexpr float kMinFlareScale = 0.02f, kMinHdrFlareScale = 0.01f;
//! A sun clipped at capture: an HDR merge that ran out of range stores its disc as a plateau
//! of one value in the channels it clipped. At least kFlatTopPixels pixels whose largest
//! channel is within kFlatTopTolerance of the region's largest is such a clip (a real peak, or
//! a bright sky's smooth crest, holds its top value in one or two pixels), and like a clipped 8-bit
//! light it needs only kMinClippedContrast times the frame's median (a sun clipped at 22-676 in
//! frames whose median is 0.1-0.3), while its flux counts each plateau pixel at clippedGain x the
//! plateau, as the 8-bit path counts its clipped pixels at clippedGain x white (only below a
//! light's contrast: above it a plateau is a rendered emitter, recorded whole).
//! The tolerance is 1.5%: lossy EXR compression (DWAA/DWAB) jitters a clipped plateau by about
//! 1%. A plateau is also most of the region's core (kMinFlatTopShare of its pixels at half its
//! largest channel or more): a bright sky's crest is a few dozen pixels of a broad region.
constexpr std::size_t kFlatTopPixels = 9;
constexpr float kFlatTopTolerance = 0.015f, kMinFlatTopShare = 0.15f, kMinClippedContrast = 50.f;
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

std::string format(const char* fmt, double a, double b = 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, a, b);
    return buf;
}

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

//! The frame's median luminance from a strided sample of at most ~64k pixels (exact enough for
//! a contrast test, one cheap pass), floored at 1e-4 so a black frame still has a scale.
float medianLuminance(const LuminanceMap& m) {
    const std::size_t stride = luminanceSampleStride(m.lum.size());
    std::vector<float> sample;
    for (std::size_t i = 0; i < m.lum.size(); i += stride) sample.push_back(m.lum[i]);
    return std::max(medianOf(sample), 1e-4f);
}

//! A pixel by its coordinates: the flood fill and the compactness count work in them, with no
//! division per pixel to recover them from an index.
struct PixelAt {
    int x = 0, y = 0;
};

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
                          std::vector<PixelAt>& members,
                          float maxRadius = std::numeric_limits<float>::infinity(),
                          Point capCentre = {}) {
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

//! Scene-referred (HDR) data: a candidate's flux gains its aureole, and a plateau between a
//! clip's contrast and a light's is a capture clip whose pixels stand for clippedGain x the
//! plateau (as a clipped 8-bit pixel stands for clippedGain x white). A plateau at a light's
//! contrast (a rendered emitter of constant radiance) is recorded whole, and one under a clip's
//! (an even sky a light was placed on) is no clip. Found and placed lights alike.
//! The contrast over the frame's median a capture-clipped plateau needs.
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

//! Two accepted candidates are one physical light when their centres lie within
//! kMergeRadii x (r_a + r_b) + kMergeSlackPx of each other: each candidate already keeps the
//! disc of twice its radius out of the search, so lights this close are the bright spots of
//! one strip, tube or window (a ceiling strip found as 4 blobs 5-7 px apart, a church window
//! twice 16 px apart), while lamps in a row stand many radii apart. The slack covers the
//! one- or two-pixel spots a thin strip breaks into.
constexpr float kMergeRadii = 2.f, kMergeSlackPx = 4.f;

//! Whether two regions are of one physical light by that rule.
bool ofOneLight(const LightCandidate& a, const LightCandidate& b) {
    const float reach = kMergeRadii * (a.radius + b.radius) + kMergeSlackPx;
    return std::hypot(a.position.x - b.position.x, a.position.y - b.position.y) <= reach;
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
    LightSearch result;
    if (image.empty()) {
        result.whyNone = "empty image";
        return result;
    }
    const LuminanceMap m = luminanceMap(image);
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

//! How far from a hand-placed point the light's peak is looked for: 2% of the frame height
//! (21 px at 1080p) covers a click beside a sun's core, not the next lamp along a street.
constexpr float kPlacedReachOfHeight = 0.02f;
constexpr float kMinPlacedReachPx = 4.f;
//! A placed light's region stops 10% of the frame height from the point: the finder refuses
//! regions larger than a light (a clipped sky, an even wall), a placed light has no verdict,
//! so its region is bounded instead; a low sun's clipped glare in a phone photo, the largest
//! light the finder takes, stays within it.
constexpr float kPlacedRegionOfHeight = 0.1f;

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
    for (const LightCandidate& light : findLights(image, all).lights)
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
