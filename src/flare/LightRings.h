// SPDX-License-Identifier: Apache-2.0
// Rings around a light candidate: the mean the finder judges prominence and glare by, and the
// aureole that carries a hazy or clipped sun's light.
#pragma once

#include "flare/LuminanceMap.h"
#include "flarekit/Flare.h"

namespace flarekit::lightfinder {

//! The ring judged for prominence: from max(2R, R + 2 px) to max(4R, R + 6 px); the rim
//! judged for a halo: from R + 1 px to 1.5R + 2 px; each sampled on 4 circles of 64 points.
constexpr int kRingCircles = 4, kRingAngles = 64;

//! Mean luminance of the ring [inner, outer] around c (pixels inside the frame only; -1 if none).
float ringMean(const LuminanceMap& m, Point c, float inner, float outer);

//! The light an aureole carries and the rings over which it kept falling.
struct Aureole {
    double flux = 0;
    int rings = 0;
};

//! The light a candidate's aureole carries: over the rings around it whose upper quartile keeps
//! falling, each ring's excess over the level where the falling stops (the local sky), times
//! its area.
Aureole measureAureole(const LuminanceMap& m, Point c, float radius);

}  // namespace flarekit::lightfinder
