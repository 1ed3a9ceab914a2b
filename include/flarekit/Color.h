// sRGB transfer functions (IEC 61966-2-1). 8-bit files are sRGB-encoded; flarekit works in
// linear light.
#pragma once

#include <cstdint>

namespace flarekit {

float srgbToLinear(float encoded);
float linearToSrgb(float linear);
//! Exact decode of an 8-bit code value through a 256-entry table.
float srgb8ToLinear(std::uint8_t code);
//! Encode, clamp to [0, 1] and round to the nearest 8-bit code.
std::uint8_t linearToSrgb8(float linear);
//! Rec. 709 luminance of linear RGB.
inline float luminance(float r, float g, float b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

}  // namespace flarekit
