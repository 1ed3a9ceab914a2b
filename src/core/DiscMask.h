// SPDX-License-Identifier: Apache-2.0
// Marking a disc in a byte mask a row span at a time: the pixels whose centres lie within
// `radius` of (cx, cy), by the same float test a pixel-by-pixel loop makes, found at each row's
// two ends (a square root and a step or two) and filled with memset between them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flarekit {

//! Whether the centre of pixel (x, y) is within `radius` of (cx, cy): the test that defines the
//! disc, in float, as the light finder has always made it.
inline bool inDisc(float cx, float cy, float radius, int x, int y) {
    const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
    return dx * dx + dy * dy <= radius * radius;
}

//! Sets mask[y * width + x] = 1 for every pixel of the width x height mask in the disc.
void markDisc(std::uint8_t* mask, int width, int height, float cx, float cy, float radius);

}  // namespace flarekit
