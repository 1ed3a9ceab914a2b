// SPDX-License-Identifier: Apache-2.0
// `flarekit blend`: whole 8-bit images through the seed-002 formulas, RGB out.
#include <array>
#include <string>

#include "flarekit/Blend.h"

namespace flarekit {

namespace {
//! The first three channels of every pixel, packed as RGB bytes.
std::vector<std::uint8_t> packRgb(const Image8& image) {
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t stride = std::size_t(image.channels);
    std::vector<std::uint8_t> rgb(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i * stride + c];
    }
    return rgb;
}
}  // namespace

std::optional<Blend8Mode> parseBlend8Mode(std::string_view name) {
    for (std::size_t i = 0; i < kBlend8ModeNames.size(); ++i) {
        if (kBlend8ModeNames[i] == name) return Blend8Mode(i);
    }
    return std::nullopt;
}

std::string_view blend8ModeName(Blend8Mode mode) {
    return kBlend8ModeNames[std::size_t(mode)];
}

Result<Image8> blendImages8(Blend8Mode mode, const Image8& src, const Image8& dst) {
    if (src.width != dst.width || src.height != dst.height) {
        return invalidInput("src and dst sizes differ: " + std::to_string(src.width) + "x" +
                            std::to_string(src.height) + " vs " + std::to_string(dst.width) + "x" +
                            std::to_string(dst.height) + ": expected the same size");
    }
    const bool srcOk = src.channels == 4 || (mode == Blend8Mode::Add && src.channels == 3);
    if (!srcOk) {
        return invalidInput(
            "src: expected RGBA (4 channels; the alpha channel is the blend alpha), got " +
            std::to_string(src.channels) + " channel(s)");
    }
    if (dst.channels != 3 && dst.channels != 4) {
        return invalidInput("dst: expected RGB or RGBA, got " + std::to_string(dst.channels) +
                            " channel(s)");
    }
    const std::size_t pixels = std::size_t(src.width) * std::size_t(src.height);

    // Work on an RGB copy of dst: the output is RGB.
    Image8 out{dst.width, dst.height, 3, packRgb(dst)};
    switch (mode) {
        case Blend8Mode::Alpha:
            blend8::alphaSpan(src.pixels.data(), out.pixels.data(), 3, pixels);
            break;
        case Blend8Mode::AlphaShift:
            blend8::alphaShiftSpan(src.pixels.data(), out.pixels.data(), 3, pixels);
            break;
        case Blend8Mode::Premultiplied: {
            std::vector<std::uint8_t> stored(pixels * 4);
            blend8::toPremultipliedInverse(src.pixels.data(), stored.data(), pixels);
            blend8::premultipliedSpan(stored.data(), out.pixels.data(), 3, pixels);
            break;
        }
        case Blend8Mode::Add: {
            // src's RGB packed so both operands are contiguous bytes for the SIMD add.
            const std::vector<std::uint8_t> rgb = packRgb(src);
            blend8::addSpanSimd(rgb.data(), out.pixels.data(), out.pixels.data(), rgb.size());
            break;
        }
    }
    return out;
}

}  // namespace flarekit
