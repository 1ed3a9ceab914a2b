// SPDX-License-Identifier: Apache-2.0
// The CPU kernel of the read-back methods: coverage from a block of depth values.
#pragma once

#include "occlusion/SunDisc.h"

namespace flarekit::occlusion {

//! Depth of the GL pixel box [x0, x0 + w) x [y0, y0 + h), rows bottom-up as glReadPixels
//! returns them. A pixel is sky (the sun visible through it) when its depth is the cleared far
//! value 1. Coverage = sum of discWeight over sky pixels / sum over all pixels (0 when the
//! disc has no weight in the box).
double coverageFromDepth(const SunDiscView& v, const float* depth, int x0, int y0, int w, int h);
//! The same from per-pixel sky fractions in [0, 1] (SkyFraction, for multisampled frames):
//! each pixel adds its weight x its fraction.
double coverageFromSkyFraction(const SunDiscView& v, const float* sky, int x0, int y0, int w,
                               int h);

}  // namespace flarekit::occlusion
