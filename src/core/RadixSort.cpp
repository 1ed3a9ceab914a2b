#include "core/RadixSort.h"

#include <array>
#include <cstddef>

#include "core/Parallel.h"

namespace flarekit {

namespace {

//! The digits of the high half, least significant first: bits 32-42, 43-53, 54-63.
constexpr std::array<int, 3> kShift = {32, 43, 54};
constexpr std::array<int, 3> kBits = {11, 11, 10};
constexpr std::size_t kBuckets = std::size_t(1) << 11;
//! Fixed slices of the keys, counted and scattered in parallel: each slice's keys of a digit
//! go after the previous slice's, so the sort stays stable whichever thread takes a slice.
constexpr std::size_t kSlices = 8;
//! Below this many keys one thread does it all: the slices would cost more than they save.
constexpr std::size_t kParallelKeys = 1 << 16;

}  // namespace

void sortByHigh32Descending(SortKeys& keys) {
    const std::size_t n = keys.size();
    const std::size_t slices = n < kParallelKeys ? 1 : kSlices;
    const auto sliceBegin = [&](std::size_t s) { return n * s / slices; };
    SortKeys other(n);  // every element is scattered to before it is read: not cleared
    // start[s][b]: where slice s puts its next key of digit b.
    std::vector<std::array<std::size_t, kBuckets>> start(slices);
    for (std::size_t pass = 0; pass < kShift.size(); ++pass) {
        const std::uint64_t mask = (std::uint64_t(1) << kBits[pass]) - 1;
        const std::size_t buckets = std::size_t(mask) + 1;
        const auto digit = [&](std::uint64_t key) {
            return std::size_t((key >> kShift[pass]) & mask);
        };
        parallelFor(0, int(slices), 1, [&](int s0, int s1) {
            for (std::size_t s = std::size_t(s0); s < std::size_t(s1); ++s) {
                start[s].fill(0);
                for (std::size_t i = sliceBegin(s); i < sliceBegin(s + 1); ++i)
                    ++start[s][digit(keys[i])];
            }
        });
        // Largest digit first; within a digit, slice 0 first.
        std::size_t at = 0;
        bool oneBucket = false;
        for (std::size_t b = buckets; b-- > 0;) {
            std::size_t total = 0;
            for (std::size_t s = 0; s < slices; ++s) {
                const std::size_t count = start[s][b];
                start[s][b] = at + total;
                total += count;
            }
            oneBucket |= total == n;
            at += total;
        }
        if (oneBucket) continue;  // every key has this digit: the order stands
        parallelFor(0, int(slices), 1, [&](int s0, int s1) {
            for (std::size_t s = std::size_t(s0); s < std::size_t(s1); ++s)
                for (std::size_t i = sliceBegin(s); i < sliceBegin(s + 1); ++i)
                    other[start[s][digit(keys[i])]++] = keys[i];
        });
        keys.swap(other);
    }
}

}  // namespace flarekit
