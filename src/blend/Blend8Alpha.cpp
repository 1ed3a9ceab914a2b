// SPDX-License-Identifier: Apache-2.0
// Span loops for the alpha modes of Tanczos 1999. Each pixel goes through the inline formula in
// Blend.h, so the exhaustive tests of the formulas cover these loops too.
#include "flarekit/Blend.h"

namespace flarekit::blend8 {

void alphaSpan(const std::uint8_t* src, std::uint8_t* dst, int dstChannels, std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i, src += 4, dst += dstChannels) {
        for (int c = 0; c < 3; ++c) dst[c] = alpha(src[c], dst[c], src[3]);
    }
}

void alphaShiftSpan(const std::uint8_t* src, std::uint8_t* dst, int dstChannels,
                    std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i, src += 4, dst += dstChannels) {
        for (int c = 0; c < 3; ++c) dst[c] = alphaShift(src[c], dst[c], src[3]);
    }
}

void toPremultipliedInverse(const std::uint8_t* src, std::uint8_t* out, std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i, src += 4, out += 4) {
        for (int c = 0; c < 3; ++c) out[c] = premultiply(src[c], src[3]);
        out[3] = std::uint8_t(255 - src[3]);
    }
}

void premultipliedSpan(const std::uint8_t* src, std::uint8_t* dst, int dstChannels,
                       std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i, src += 4, dst += dstChannels) {
        for (int c = 0; c < 3; ++c) dst[c] = premultiplied(src[c], dst[c], src[3]);
    }
}

}  // namespace flarekit::blend8
