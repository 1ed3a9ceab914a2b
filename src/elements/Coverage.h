// SPDX-License-Identifier: Apache-2.0
// Antialiasing by box filtering in one dimension: the fraction of a filter window of width
// `filter` centred at x that overlaps an interval. Box filtering a shape keeps its integral,
// which is what lets the element tests compare pixel sums with analytic areas.
#pragma once

#include <algorithm>

namespace flarekit::coverage {

//! Overlap of [x - filter/2, x + filter/2] with [lo, hi], divided by filter (0..1).
inline float interval(float x, float lo, float hi, float filter) {
    const float overlap = std::min(x + 0.5f * filter, hi) - std::max(x - 0.5f * filter, lo);
    return std::clamp(overlap / filter, 0.f, 1.f);
}

//! interval() for (-inf, edge]: a linear ramp from 1 to 0 across [edge - filter/2, edge +
//! filter/2].
inline float below(float x, float edge, float filter) {
    return std::clamp((edge - x) / filter + 0.5f, 0.f, 1.f);
}

}  // namespace flarekit::coverage
