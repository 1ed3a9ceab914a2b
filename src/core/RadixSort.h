// SPDX-License-Identifier: Apache-2.0
// Ordering 64-bit keys by their high 32 bits, largest first, lazily: one stable counting pass
// splits the keys into ranges of high halves (buckets), largest first, and a caller sorts a
// bucket only when it reaches it, after dropping the keys it no longer needs. The light finder
// visits its seeds this way: once the first lights are grown most seeds are already taken, so
// most of a full sort's work (three passes over every key) would be thrown away.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "flarekit/Image.h"

namespace flarekit {

//! Keys in pixel memory (Image.h): a frame's worth is megabytes, filled whole when made.
using SortKeys = std::vector<std::uint64_t, PixelAllocator<std::uint64_t>>;

//! Keys grouped by their high halves: every key of bucket k has a larger high half than every
//! key of bucket k + 1, and within a bucket the keys keep their order in the input.
struct HighBuckets {
    SortKeys keys;
    std::vector<std::size_t> begin;  //!< bucket k is keys[begin[k], begin[k + 1])
    std::size_t count() const { return begin.empty() ? 0 : begin.size() - 1; }
};

//! Groups `keys`, whose high halves all lie in [low, high], into at most 2048 buckets of equal
//! spans of high halves, largest first.
HighBuckets bucketByHigh32Descending(SortKeys keys, std::uint32_t low, std::uint32_t high);

//! Sorts keys[first, last) largest first (whole keys: ties of the high half by the low half).
void sortDescending(SortKeys& keys, std::size_t first, std::size_t last);

}  // namespace flarekit
