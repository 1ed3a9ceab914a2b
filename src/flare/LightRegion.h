// SPDX-License-Identifier: Apache-2.0
// What the light finder (LightFinder.cpp) and a hand-placed light (PlacedLight.cpp) share: a
// candidate's region grown from its peak and measured, the scene-referred flux of its aureole
// and of a capture clip (LightRegion.cpp), the rule that makes regions one physical light, and
// the search over a luminance map already made.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "flare/LuminanceMap.h"
#include "flarekit/Flare.h"

namespace flarekit::lightfinder {

//! In scene-referred (HDR) data a light stands far above the frame's exposure: its peak is at
//! least this many times the frame's median luminance. Real suns and lamps are 10^3-10^6 x
//! (blender-data HDRIs: suns of 950-33,000 over medians of 0.1-0.25, 8,000-300,000 x; night
//! lamps of 4,000 over 0.013); a bright sky through an arch, a sun's broken fringe or a lit
//! cloud 5-250 x.
inline constexpr float kMinKeyContrast = 1000.f;
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
inline constexpr std::size_t kFlatTopPixels = 9;
inline constexpr float kFlatTopTolerance = 0.015f, kMinFlatTopShare = 0.15f,
                       kMinClippedContrast = 50.f;

//! printf with up to two numbers, for verdicts and warnings.
std::string format(const char* fmt, double a, double b = 0);
//! The frame's median luminance from a strided sample of at most ~64k pixels (exact enough for
//! a contrast test, one cheap pass), floored at 1e-4 so a black frame still has a scale.
float medianLuminance(const LuminanceMap& m);

//! A pixel by its coordinates: the flood fill and the compactness count work in them, with no
//! division per pixel to recover them from an index.
struct PixelAt {
    int x = 0, y = 0;
};

//! The luminance a light's region is grown down to from its `peak`: its core (nearPeak of the
//! peak) in 8/16-bit data, where everything near the clip is the light; in HDR down to a
//! quarter of it, but never below the core when that is under 1 (a dim peak's fringe).
float regionThreshold(float peak, float nearPeak, bool displayReferred);

//! Grows the region of `seed` over unseen pixels >= threshold (whose centres lie within
//! `maxRadius` px of `capCentre`) and measures it.
LightCandidate growRegion(const LuminanceMap& m, const Image* image, std::size_t seed,
                          float threshold, float clippedGain, bool displayReferred,
                          std::vector<std::uint8_t>& seen, std::vector<PixelAt>& stack,
                          std::vector<PixelAt>& members,
                          float maxRadius = std::numeric_limits<float>::infinity(),
                          Point capCentre = {});

//! The contrast over the frame's median a capture-clipped plateau needs.
float clipContrast(const LightCandidate& c, const LuminanceMap& m);

//! Scene-referred (HDR) data: a candidate's flux gains its aureole, and a plateau between a
//! clip's contrast and a light's is a capture clip whose pixels stand for clippedGain x the
//! plateau (as a clipped 8-bit pixel stands for clippedGain x white). A plateau at a light's
//! contrast (a rendered emitter of constant radiance) is recorded whole, and one under a clip's
//! (an even sky a light was placed on) is no clip. Found and placed lights alike.
void addSceneReferredFlux(LightCandidate& c, const LuminanceMap& m, float frameKey,
                          float clippedGain);

//! Two accepted candidates are one physical light when their centres lie within
//! 2 (r_a + r_b) + 4 px of each other (LightRegion.cpp says why).
bool ofOneLight(const LightCandidate& a, const LightCandidate& b);

//! findLights over the luminance map of `image` already made.
LightSearch findLightsIn(const LuminanceMap& m, const Image& image,
                         const LightSearchOptions& options);

}  // namespace flarekit::lightfinder
