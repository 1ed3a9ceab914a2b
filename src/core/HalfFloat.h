// SPDX-License-Identifier: Apache-2.0
// IEEE binary16 conversions of whole pixel rows, on the CPU's F16C instructions where it has
// them (every x86-64 since 2012) and Imath's half otherwise; both round to nearest, ties to
// even, so the results are the same bits.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flarekit {

//! The largest finite half float. An infinity read from a file is clamped to it (in a half
//! file it is what a renderer's overflow left: a light brighter than the format holds, not a
//! hole), and values past it are clamped to it on writing, so a half file flarekit writes
//! never holds an infinity.
inline constexpr float kLargestHalf = 65504.f;

//! A sample as flarekit reads it: NaN as 0, an infinity as +-kLargestHalf, others as they are.
inline float sanitisedSample(float v) {
    if (v != v) return 0.f;
    return v > kLargestHalf ? kLargestHalf : v < -kLargestHalf ? -kLargestHalf : v;
}

//! `pixels` float RGBA pixels to `channels` (1-4) packed halves per pixel; NaN becomes 0,
//! values past +-65504 (infinities included) become +-65504, the largest finite half.
void floatsToHalf(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out);
//! `count` halves to floats, exactly.
void halfsToFloats(const std::uint16_t* in, std::size_t count, float* out);

}  // namespace flarekit
