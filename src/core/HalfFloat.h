// SPDX-License-Identifier: Apache-2.0
// IEEE binary16 conversions of whole pixel rows, on the CPU's F16C instructions where it has
// them (every x86-64 since 2012) and Imath's half otherwise; both round to nearest, ties to
// even, so the results are the same bits.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flarekit {

//! `pixels` float RGBA pixels to `channels` (1-4) packed halves per pixel; NaN and infinities
//! become 0 (as the file writers have always done), values past 65504 become infinity (as
//! Imath's half: the format has no larger value).
void floatsToHalf(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out);
//! `count` halves to floats, exactly.
void halfsToFloats(const std::uint16_t* in, std::size_t count, float* out);

}  // namespace flarekit
