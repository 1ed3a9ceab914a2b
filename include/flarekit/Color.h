// SPDX-License-Identifier: Apache-2.0
// sRGB transfer functions (IEC 61966-2-1). 8-bit files are sRGB-encoded; flarekit works in
// linear light.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace flarekit {

float srgbToLinear(float encoded);
float linearToSrgb(float linear);
//! Exact decode of an 8-bit code value through a 256-entry table.
float srgb8ToLinear(std::uint8_t code);
//! The 256 and 65536 decoded values behind srgb8ToLinear and srgb16ToLinear, for loops that
//! look up many codes.
const float* srgb8DecodeTable();
const float* srgb16DecodeTable();
//! Exact decode of a 16-bit code value (code / 65535) through a 65536-entry table.
float srgb16ToLinear(std::uint16_t code);
//! Encode, clamp to [0, 1] and round to the nearest 8-bit code: correctly rounded (the code
//! whose decoded interval holds the value), NaN to 0, through a table (no pow).
std::uint8_t linearToSrgb8(float linear);
//! The same to the nearest 16-bit code.
std::uint16_t linearToSrgb16(float linear);

//! Linear alpha to a code: clamped to [0, 1], rounded to nearest, NaN to 0.
inline std::uint8_t alphaTo8(float a) {
    return a > 0.f ? std::uint8_t(std::lround(std::min(a, 1.f) * 255.f)) : 0;
}
inline std::uint16_t alphaTo16(float a) {
    return a > 0.f ? std::uint16_t(std::lround(std::min(a, 1.f) * 65535.f)) : 0;
}

//! `pixels` float RGBA pixels to `channels` (3: RGB, 4: RGBA) interleaved codes: sRGB colour as
//! linearToSrgb8/16, linear alpha as alphaTo8/16, NaN and infinities as 0 (what the file
//! writers have always done). One pass, no pow.
void encodeSrgb8(const float* rgba, std::size_t pixels, int channels, std::uint8_t* out);
void encodeSrgb16(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out);
//! The same layout with every channel quantised as it is (round(clamp(v, 0, 1) x 255 or
//! 65535)): values already encoded for their colour space (an OCIO output transform's).
void encodeDirect8(const float* rgba, std::size_t pixels, int channels, std::uint8_t* out);
void encodeDirect16(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out);
//! Rec. 709 luminance of linear RGB.
inline float luminance(float r, float g, float b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

}  // namespace flarekit
