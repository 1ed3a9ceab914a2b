#include "flarekit/Color.h"

#include <algorithm>
#include <array>
#include <cmath>

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

float srgb8ToLinear(std::uint8_t code) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = srgbToLinear(float(i) / 255.f);
        return t;
    }();
    return table[code];
}

std::uint8_t linearToSrgb8(float linear) {
    // Rounding to the nearest code without pow: code k covers linear values from the decode of
    // (k - 0.5)/255 up to that of (k + 0.5)/255, so a binary search over the 255 boundaries
    // (computed once, in double) gives the correctly rounded code in 8 comparisons.
    static const std::array<float, 255> bounds = [] {
        std::array<float, 255> b{};
        for (int k = 0; k < 255; ++k) {
            const double e = (k + 0.5) / 255.0;
            b[std::size_t(k)] =
                float(e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4));
        }
        return b;
    }();
    if (!(linear > 0.f)) return 0;  // also maps NaN to 0
    if (linear >= 1.f) return 255;
    return std::uint8_t(std::upper_bound(bounds.begin(), bounds.end(), linear) - bounds.begin());
}

}  // namespace flarekit
