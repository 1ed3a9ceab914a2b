// SPDX-License-Identifier: Apache-2.0
// The sRGB encoders against independent references: a binary search over the code boundaries
// (the previous implementation) and the IEC 61966-2-1 curve evaluated in double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "flarekit/Color.h"

using namespace flarekit;

namespace {

double decode(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
double encode(double x) {
    return x <= 0.0031308 ? x * 12.92 : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

//! The code of x by binary search over the levels' boundaries (each the decode of a half code).
int referenceCode(float x, int levels) {
    static std::vector<float> bounds8, bounds16;
    std::vector<float>& bounds = levels == 255 ? bounds8 : bounds16;
    if (bounds.empty()) {
        for (int k = 0; k < levels; ++k) bounds.push_back(float(decode((k + 0.5) / levels)));
    }
    if (!(x > 0.f)) return 0;
    if (x >= 1.f) return levels;
    return int(std::upper_bound(bounds.begin(), bounds.end(), x) - bounds.begin());
}

}  // namespace

TEST(Color, EveryCodeSurvivesDecodeAndEncode) {
    for (int code = 0; code < 256; ++code)
        EXPECT_EQ(linearToSrgb8(srgb8ToLinear(std::uint8_t(code))), code);
    for (int code = 0; code < 65536; ++code)
        ASSERT_EQ(linearToSrgb16(srgb16ToLinear(std::uint16_t(code))), code) << code;
    EXPECT_NEAR(srgbToLinear(0.5f), 0.214041f, 1e-5f);  // IEC 61966-2-1
    EXPECT_FLOAT_EQ(srgb16ToLinear(65535), 1.f);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(linearToSrgb8(7.f), 255);
    EXPECT_EQ(linearToSrgb8(-0.5f), 0);
    EXPECT_EQ(linearToSrgb16(7.f), 65535);
}

TEST(Color, EncodeMatchesTheBoundarySearchAtEveryBoundaryAndAcrossASweep) {
    for (int levels : {255, 65535}) {
        auto code = [&](float x) {
            return levels == 255 ? int(linearToSrgb8(x)) : int(linearToSrgb16(x));
        };
        // Each boundary and the floats either side of it: the values where rounding turns.
        for (int k = 0; k < levels; ++k) {
            const float b = float(decode((k + 0.5) / levels));
            for (float x : {std::nextafter(b, 0.f), b, std::nextafter(b, 2.f)})
                ASSERT_EQ(code(x), referenceCode(x, levels)) << levels << " " << x;
        }
        // Every 61st float from 0 to just past 1 (17 million values), so every table bucket,
        // one at a time and through the bulk encoder (RGB of float RGBA, blocks of 4096).
        std::vector<float> rgba;
        std::vector<int> expected;
        const auto checkBulk = [&] {
            const std::size_t n = expected.size();
            std::vector<int> got(n * 3);
            if (levels == 255) {
                std::vector<std::uint8_t> out(n * 3);
                encodeSrgb8(rgba.data(), n, 3, out.data());
                got.assign(out.begin(), out.end());
            } else {
                std::vector<std::uint16_t> out(n * 3);
                encodeSrgb16(rgba.data(), n, 3, out.data());
                got.assign(out.begin(), out.end());
            }
            for (std::size_t i = 0; i < got.size(); ++i)
                ASSERT_EQ(got[i], expected[i / 3]) << levels << " " << rgba[i / 3 * 4];
            rgba.clear();
            expected.clear();
        };
        for (std::uint32_t bits = 0; bits <= 0x3F800100u; bits += 61) {
            const float x = std::bit_cast<float>(bits);
            const int reference = referenceCode(x, levels);
            ASSERT_EQ(code(x), reference) << levels << " " << x;
            rgba.insert(rgba.end(), {x, x, x, 1.f});
            expected.push_back(reference);
            if (expected.size() == 4096) checkBulk();
        }
        checkBulk();
    }
}

TEST(Color, EncodeIsTheCorrectlyRoundedCurve) {
    // Against the curve itself in double: within half a code, up to the float rounding of the
    // boundaries (a few millionths of a code).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> logX(-24.0, 0.1);
    for (int i = 0; i < 200000; ++i) {
        const float x = float(std::pow(10.0, logX(rng) / 4.0 * 2.0));
        const double e = encode(std::min(double(x), 1.0));
        EXPECT_LE(std::abs(e * 255 - linearToSrgb8(x)), 0.5 + 1e-4) << x;
        // 16-bit codes near 1.0 are only ~600 float steps apart: half a code, plus one step.
        ASSERT_LE(std::abs(e * 65535 - linearToSrgb16(x)), 0.5 + 2e-3) << x;
    }
}

TEST(Color, BulkEncodeIsTheScalarEncodeWithNonFiniteAsZero) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(-0.2f, 1.3f);
    std::vector<float> rgba(4 * 1000);
    for (float& v : rgba) v = value(rng);
    // The values the encoder's range checks turn on: every non-finite kind, both zeros, the
    // smallest subnormal, the edges of the table (2^-13 and 2^-21) and of 1.
    const float inf = std::numeric_limits<float>::infinity();
    const float edges[] = {inf,
                           -inf,
                           std::numeric_limits<float>::quiet_NaN(),
                           -std::numeric_limits<float>::quiet_NaN(),
                           0.f,
                           -0.f,
                           std::numeric_limits<float>::denorm_min(),
                           std::ldexp(1.f, -13),
                           std::nextafter(std::ldexp(1.f, -13), 0.f),
                           std::ldexp(1.f, -21),
                           std::nextafter(std::ldexp(1.f, -21), 0.f),
                           1.f,
                           std::nextafter(1.f, 0.f),
                           std::numeric_limits<float>::max(),
                           -std::numeric_limits<float>::max()};
    for (std::size_t i = 0; i < std::size(edges); ++i) rgba[i * 3] = edges[i];
    for (int channels : {3, 4}) {
        std::vector<std::uint8_t> out8(1000 * std::size_t(channels));
        std::vector<std::uint16_t> out16(out8.size());
        encodeSrgb8(rgba.data(), 1000, channels, out8.data());
        encodeSrgb16(rgba.data(), 1000, channels, out16.data());
        for (std::size_t p = 0; p < 1000; ++p) {
            for (int c = 0; c < channels; ++c) {
                float v = rgba[p * 4 + std::size_t(c)];
                if (!std::isfinite(v)) v = 0.f;
                const std::size_t i = p * std::size_t(channels) + std::size_t(c);
                ASSERT_EQ(out8[i], c < 3 ? linearToSrgb8(v) : alphaTo8(v)) << p << " " << c;
                ASSERT_EQ(out16[i], c < 3 ? linearToSrgb16(v) : alphaTo16(v)) << p << " " << c;
            }
        }
    }
    EXPECT_EQ(linearToSrgb8(inf), 255);  // the scalar encode clamps +inf; the bulk gives it 0
    EXPECT_EQ(linearToSrgb16(inf), 65535);
    EXPECT_EQ(alphaTo8(0.5f), 128);  // round half away from zero, as std::lround
    EXPECT_EQ(alphaTo16(2.f), 65535);
}
