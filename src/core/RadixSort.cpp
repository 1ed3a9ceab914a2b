// SPDX-License-Identifier: Apache-2.0
#include "core/RadixSort.h"

#include <algorithm>
#include <array>
#include <bit>
#include <functional>

#include "core/Parallel.h"

namespace flarekit {

namespace {

//! Buckets at most: 2^11 counters per slice stay in L1, and the scatter writes to few enough
//! places at once to keep its stores in cache.
constexpr int kBucketBits = 11;
constexpr std::size_t kMaxBuckets = std::size_t(1) << kBucketBits;
//! Fixed slices of the keys, counted and scattered in parallel: each slice's keys of a bucket
//! go after the previous slice's, so the grouping stays stable whichever thread takes a slice.
constexpr std::size_t kSlices = 8;
//! Below this many keys one thread does it all: the slices would cost more than they save.
constexpr std::size_t kParallelKeys = 1 << 16;

}  // namespace

HighBuckets bucketByHigh32Descending(SortKeys keys, std::uint32_t low, std::uint32_t high) {
    HighBuckets out;
    const std::size_t n = keys.size();
    if (n == 0 || high < low) {
        out.keys = std::move(keys);
        out.begin = {0, n};
        return out;
    }
    // The span of high halves, cut to kBucketBits: bucket b holds (high - half) >> shift == b,
    // so bucket 0 is the largest.
    const int spanBits = int(std::bit_width(std::uint64_t(high) - low));
    const int shift = std::max(0, spanBits - kBucketBits);
    const std::size_t buckets = std::size_t(((std::uint64_t(high) - low) >> shift) + 1);
    const auto bucketOf = [&](std::uint64_t key) {
        return std::size_t((high - std::uint32_t(key >> 32)) >> shift);
    };
    const std::size_t slices = n < kParallelKeys ? 1 : kSlices;
    const auto sliceBegin = [&](std::size_t s) { return n * s / slices; };
    // start[s][b]: where slice s puts its next key of bucket b.
    std::vector<std::array<std::size_t, kMaxBuckets>> start(slices);
    parallelFor(0, int(slices), 1, [&](int s0, int s1) {
        for (std::size_t s = std::size_t(s0); s < std::size_t(s1); ++s) {
            start[s].fill(0);
            for (std::size_t i = sliceBegin(s); i < sliceBegin(s + 1); ++i)
                ++start[s][bucketOf(keys[i])];
        }
    });
    out.begin.resize(buckets + 1);
    std::size_t at = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
        out.begin[b] = at;
        for (std::size_t s = 0; s < slices; ++s) {
            const std::size_t count = start[s][b];
            start[s][b] = at;
            at += count;
        }
    }
    out.begin[buckets] = n;
    out.keys = SortKeys(n);  // every element is scattered to: not cleared
    parallelFor(0, int(slices), 1, [&](int s0, int s1) {
        for (std::size_t s = std::size_t(s0); s < std::size_t(s1); ++s)
            for (std::size_t i = sliceBegin(s); i < sliceBegin(s + 1); ++i)
                out.keys[start[s][bucketOf(keys[i])]++] = keys[i];
    });
    return out;
}

void sortDescending(SortKeys& keys, std::size_t first, std::size_t last) {
    const auto b = keys.begin() + std::ptrdiff_t(first), e = keys.begin() + std::ptrdiff_t(last);
    // Ties of the high half made in raster order are already in order (an 8-bit frame's clipped
    // white is one long tie): checking costs one pass, sorting them would cost log n.
    if (!std::is_sorted(b, e, std::greater<>())) std::sort(b, e, std::greater<>());
}

}  // namespace flarekit
