// SPDX-License-Identifier: Apache-2.0
// What the light finder and the post-process exposure both read off a frame before any real
// work: whether it is display-referred, and its median from a strided sample.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace flarekit {

//! Pixels a frame summary reads at most: ~64k at a fixed stride is exact enough for a median
//! or a metered mean, and costs a sliver of one pass over a 1080p frame.
inline constexpr std::size_t kLuminanceSamples = 65536;
inline std::size_t luminanceSampleStride(std::size_t pixels) {
    return std::max<std::size_t>(1, pixels / kLuminanceSamples);
}

//! The median of `sample`, reordered in place (0 when empty).
inline float medianOf(std::vector<float>& sample) {
    if (sample.empty()) return 0.f;
    const auto middle = sample.begin() + std::ptrdiff_t(sample.size() / 2);
    std::nth_element(sample.begin(), middle, sample.end());
    return *middle;
}

//! 8/16-bit data holds nothing above display white; a frame whose brightest channel passes it
//! (by more than float noise, 1e-3) is scene-referred HDR.
inline bool isDisplayReferred(float brightestChannel) {
    return !(brightestChannel > 1.f + 1e-3f);
}

}  // namespace flarekit
