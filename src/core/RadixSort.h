// A stable LSD radix sort of 64-bit keys by their high 32 bits, largest first: three counting
// passes of 11, 11 and 10 bits over the keys, where a comparison sort makes log2(n) (about 20
// for a frame's worth), each counted and scattered on every core in fixed slices. A pass whose
// digit is the same in every key is skipped.
#pragma once

#include <cstdint>
#include <vector>

#include "flarekit/Image.h"

namespace flarekit {

//! Keys in pixel memory (Image.h): a frame's worth is megabytes, filled whole when made.
using SortKeys = std::vector<std::uint64_t, PixelAllocator<std::uint64_t>>;

//! Reorders `keys` by (key >> 32), largest first; keys with equal high halves keep their order.
void sortByHigh32Descending(SortKeys& keys);

}  // namespace flarekit
