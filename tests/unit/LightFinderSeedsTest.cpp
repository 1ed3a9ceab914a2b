// SPDX-License-Identifier: Apache-2.0
// The light finder's seed order: the luminance keys bucketed by their high half and sorted
// bucket by bucket are a plain descending sort.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>

#include "LightImages.h"
#include "core/RadixSort.h"
#include "flarekit/Flare.h"

using namespace flarekit;
using namespace flarekit::test;

// The seed order: the keys, made in raster order, grouped by their luminance half and each
// group sorted, are in the order of a plain descending sort of the whole keys (ties in raster
// order), on frames whose luminances tie a lot (8-bit steps), on ones that use every digit
// (random floats) and on one long tie (clipped white).
TEST(LightFinderSeeds, BucketsSortedOneByOneAreTheDescendingOrder) {
    std::mt19937 rng(11);
    const auto bitsOf = [](float l) {
        std::uint32_t bits;
        std::memcpy(&bits, &l, sizeof bits);
        return bits;
    };
    // 1,000 keys: one thread; 200,000: in slices on every core.
    for (const std::uint32_t count : {1000u, 200000u})
        for (const int kind : {0, 1, 2}) {
            SortKeys keys;
            const float top = kind == 1 ? 40000.f : 1.f;
            for (std::uint32_t i = 0; i < count; ++i) {
                float l = std::uniform_real_distribution<float>(0.25f, top)(rng);
                if (kind == 0) l = std::round(l * 255.f) / 255.f;
                if (kind == 2) l = 1.f;
                keys.push_back((std::uint64_t(bitsOf(l)) << 32) | (0xFFFFFFFFu - i));
            }
            SortKeys expected = keys;
            std::sort(expected.begin(), expected.end(), std::greater<>());
            HighBuckets buckets = bucketByHigh32Descending(keys, bitsOf(0.25f), bitsOf(top));
            ASSERT_LE(buckets.count(), 2048u);
            ASSERT_EQ(buckets.begin.front(), 0u);
            ASSERT_EQ(buckets.begin.back(), keys.size());
            for (std::size_t b = 0; b < buckets.count(); ++b)
                sortDescending(buckets.keys, buckets.begin[b], buckets.begin[b + 1]);
            EXPECT_EQ(buckets.keys, expected) << count << " " << kind;
            if (kind == 1) {
                EXPECT_GT(buckets.count(), 1000u);  // a span of 2^28: all 2048 used
            }
        }
    const HighBuckets none = bucketByHigh32Descending({}, 0, 100);
    EXPECT_EQ(none.count(), 1u);
    EXPECT_TRUE(none.keys.empty());
    const HighBuckets one = bucketByHigh32Descending({42}, 0, 0);
    EXPECT_EQ(one.keys, SortKeys{42});
    EXPECT_EQ(one.count(), 1u);
}
