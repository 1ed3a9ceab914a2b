// A stable LSD radix sort of 64-bit keys by their high 32 bits, largest first: three counting
// passes of 11, 11 and 10 bits over the keys, where a comparison sort makes log2(n) (about 20
// for a frame's worth), each counted and scattered on every core in fixed slices. A pass whose
// digit is the same in every key is skipped.
#pragma once

#include <cstdint>
#include <vector>

namespace flarekit {

//! Reorders `keys` by (key >> 32), largest first; keys with equal high halves keep their order.
void sortByHigh32Descending(std::vector<std::uint64_t>& keys);

}  // namespace flarekit
