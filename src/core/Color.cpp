// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Color.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <vector>

namespace flarekit {

// IEC 61966-2-1 piecewise curve: linear segment below 0.04045 (encoded) / 0.0031308 (linear).
float srgbToLinear(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float linear) {
    if (linear <= 0.0031308f) return linear * 12.92f;
    return 1.055f * std::pow(linear, 1.f / 2.4f) - 0.055f;
}

namespace {

//! The decode of encoded value e, in double: the code boundaries are computed from it.
double decodeDouble(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

//! Correct rounding of an encode to `levels` codes without pow: code k covers the linear values
//! from the decode of (k - 0.5)/levels up to that of (k + 0.5)/levels, so the code of x is the
//! number of those boundaries at or below x. A first guess comes from a table indexed by the
//! float's exponent and top mantissa bits (`kBucketBits` of them): `buckets[b].code` is the code
//! at the bottom of bucket b, and the answer lies between it and the next bucket's code.
template <typename Code, int kLevels, int kMinExponent, int kBucketBits, bool kOneBoundaryPerBucket>
struct EncodeTable {
    static constexpr int kShift = 23 - kBucketBits;
    //! Bits of 2^kMinExponent: every value below it is below the first boundary (code 0).
    static constexpr std::uint32_t kFirstBits = std::uint32_t(127 + kMinExponent) << 23;
    static constexpr std::uint32_t kOneBits = 0x3F800000u;  //!< 1.0f
    static constexpr std::uint32_t kInfinityBits = 0x7F800000u;
    static constexpr std::size_t kBuckets = std::size_t(-kMinExponent) << kBucketBits;

    //! A bucket's first code and the boundary above it, side by side: one load finds both.
    struct Bucket {
        float bound;
        Code code;
    };

    std::vector<float> bounds;    //!< kLevels boundaries, then +inf
    std::vector<Bucket> buckets;  //!< kBuckets + 1

    EncodeTable() : bounds(kLevels + 1), buckets(kBuckets + 1) {
        for (int k = 0; k < kLevels; ++k)
            bounds[std::size_t(k)] = float(decodeDouble((k + 0.5) / kLevels));
        bounds[kLevels] = INFINITY;
        for (std::size_t b = 0; b <= kBuckets; ++b) {
            const float lo = std::bit_cast<float>(kFirstBits + std::uint32_t(b << kShift));
            const auto code = std::size_t(std::upper_bound(bounds.begin(), bounds.end() - 1, lo) -
                                          bounds.begin());
            buckets[b] = {bounds[code], Code(code)};
        }
    }

    //! The code of a linear value: 0 for NaN, negatives and values below the first boundary,
    //! kLevels for 1 and above, +inf included unless kInfinityAsZero (the bulk encoders give
    //! every non-finite value 0, what the file writers have always written). The sign, NaN and
    //! infinity tests are unsigned range checks on the float's bits.
    template <bool kInfinityAsZero = false>
    Code encode(float linear) const {
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(linear);
        if (bits - kFirstBits >= kOneBits - kFirstBits) {  // outside [2^kMinExponent, 1)
            const std::uint32_t top = kInfinityBits - kOneBits - (kInfinityAsZero ? 1 : 0);
            return bits - kOneBits <= top ? Code(kLevels) : Code(0);
        }
        const Bucket& b = buckets[(bits - kFirstBits) >> kShift];
        if constexpr (kOneBoundaryPerBucket) {
            return Code(b.code + (linear >= b.bound));  // branch-free: one step at most
        } else {
            Code code = b.code;
            while (linear >= bounds[code]) ++code;  // at most a few steps: see the bucket sizes
            return code;
        }
    }
};

// 8-bit: with 8 mantissa bits a bucket is narrower than the code spacing everywhere in [0, 1]
// (0.002 wide below 1, where codes are 0.009 apart; 3e-4 apart on the linear segment), so the
// loop runs at most once (one comparison, branch-free). Values below 2^-13 (1.2e-4) are under the
// first boundary (1.5e-4).
using Encode8 = EncodeTable<std::uint8_t, 255, -13, 8, true>;
// 16-bit: the first boundary is 5.9e-7, above 2^-21; 10 mantissa bits keep a bucket within
// about 14 codes near 1.0.
using Encode16 = EncodeTable<std::uint16_t, 65535, -21, 10, false>;

float finiteOr0(float v) {
    return std::isfinite(v) ? v : 0.f;
}

const Encode8& encode8() {
    static const Encode8 table;
    return table;
}
const Encode16& encode16() {
    static const Encode16 table;
    return table;
}

}  // namespace

const float* srgb8DecodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = srgbToLinear(float(i) / 255.f);
        return t;
    }();
    return table.data();
}

const float* srgb16DecodeTable() {
    static const std::vector<float> table = [] {
        std::vector<float> t(65536);
        for (std::size_t i = 0; i < t.size(); ++i) t[i] = srgbToLinear(float(i) / 65535.f);
        return t;
    }();
    return table.data();
}

float srgb8ToLinear(std::uint8_t code) {
    return srgb8DecodeTable()[code];
}

float srgb16ToLinear(std::uint16_t code) {
    return srgb16DecodeTable()[code];
}

std::uint8_t linearToSrgb8(float linear) {
    return encode8().encode(linear);
}

std::uint16_t linearToSrgb16(float linear) {
    return encode16().encode(linear);
}

void encodeSrgb8(const float* rgba, std::size_t pixels, int channels, std::uint8_t* out) {
    const Encode8& table = encode8();
    for (std::size_t p = 0; p < pixels; ++p, rgba += 4, out += channels) {
        out[0] = table.encode<true>(rgba[0]);
        out[1] = table.encode<true>(rgba[1]);
        out[2] = table.encode<true>(rgba[2]);
        if (channels == 4) out[3] = alphaTo8(finiteOr0(rgba[3]));
    }
}

void encodeSrgb16(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out) {
    const Encode16& table = encode16();
    for (std::size_t p = 0; p < pixels; ++p, rgba += 4, out += channels) {
        out[0] = table.encode<true>(rgba[0]);
        out[1] = table.encode<true>(rgba[1]);
        out[2] = table.encode<true>(rgba[2]);
        if (channels == 4) out[3] = alphaTo16(finiteOr0(rgba[3]));
    }
}

void encodeDirect8(const float* rgba, std::size_t pixels, int channels, std::uint8_t* out) {
    for (std::size_t p = 0; p < pixels; ++p, rgba += 4, out += channels)
        for (int c = 0; c < channels; ++c) out[c] = alphaTo8(finiteOr0(rgba[c]));
}

void encodeDirect16(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out) {
    for (std::size_t p = 0; p < pixels; ++p, rgba += 4, out += channels)
        for (int c = 0; c < channels; ++c) out[c] = alphaTo16(finiteOr0(rgba[c]));
}

}  // namespace flarekit
