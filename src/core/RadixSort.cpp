#include "core/RadixSort.h"

#include <array>
#include <cstddef>

namespace flarekit {

void sortByHigh32Descending(std::vector<std::uint64_t>& keys) {
    // The digits of the high half, least significant first: bits 32-42, 43-53, 54-63.
    constexpr std::array<int, 3> kShift = {32, 43, 54};
    constexpr std::array<int, 3> kBits = {11, 11, 10};
    std::vector<std::uint64_t> other(keys.size());
    std::vector<std::size_t> start(std::size_t(1) << 11);
    for (std::size_t pass = 0; pass < kShift.size(); ++pass) {
        const std::uint64_t mask = (std::uint64_t(1) << kBits[pass]) - 1;
        const std::size_t buckets = std::size_t(mask) + 1;
        const auto digit = [&](std::uint64_t key) {
            return std::size_t((key >> kShift[pass]) & mask);
        };
        std::fill(start.begin(), start.end(), 0);
        for (const std::uint64_t key : keys) ++start[digit(key)];
        bool oneBucket = false;
        for (std::size_t b = 0; b < buckets; ++b) oneBucket |= start[b] == keys.size();
        if (oneBucket) continue;  // every key has this digit: the order stands
        // Largest digit first: bucket b starts after every bucket above it.
        std::size_t at = 0;
        for (std::size_t b = buckets; b-- > 0;) {
            const std::size_t count = start[b];
            start[b] = at;
            at += count;
        }
        for (const std::uint64_t key : keys) other[start[digit(key)]++] = key;
        keys.swap(other);
    }
}

}  // namespace flarekit
