#include "flarekit/Color.h"

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
    if (!(linear > 0.f)) return 0;  // also maps NaN to 0
    if (linear >= 1.f) return 255;
    return std::uint8_t(std::lround(linearToSrgb(linear) * 255.f));
}

}  // namespace flarekit
