// SPDX-License-Identifier: Apache-2.0
// Which ghosts a lens render draws for a light, and where: the light's field angle from its
// place on the sensor, the brightest ghosts at that angle, and (ghostsOnImage, Lens.h) each
// drawn ghost's place on the image.
#pragma once

#include <array>
#include <vector>

#include "flarekit/Lens.h"
#include "lens/LensTrace.h"

namespace flarekit::lens {

//! The field angle (degrees) whose direct image's centroid lands at display point (x, y) mm:
//! paraxial first, then corrected twice by the traced centroid (distortion).
std::array<double, 2> fieldAngle(const TraceLens& t, double focal, double x, double y);

//! The `count` brightest ghosts at `angle` (pairs of surfaces) and the brightest one's share of
//! the light (luminance-weighted over its RGB figures; 0 when none reaches the sensor).
struct PickedGhosts {
    std::vector<std::array<int, 2>> pairs;
    double share = 0;
};

PickedGhosts pickGhosts(const Lens& lens, std::array<double, 2> angle, int count);

}  // namespace flarekit::lens
