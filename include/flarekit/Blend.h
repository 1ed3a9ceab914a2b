// SPDX-License-Identifier: Apache-2.0
// Blending. The 8-bit modes are the integer formulas of Tanczos, "The Art of Modeling Lens
// Flares" (Tanczos, 1999), bit for bit; the float modes composite linear-light HDR images.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "flarekit/Image.h"
#include "flarekit/Result.h"

namespace flarekit {

// ---- 8-bit, exact (Tanczos 1999) ------------------------------------------------------------

enum class Blend8Mode { Alpha, AlphaShift, Premultiplied, Add };
//! The modes' names, in Blend8Mode's order.
inline constexpr std::array<std::string_view, 4> kBlend8ModeNames = {"alpha", "alpha-shift",
                                                                     "premultiplied", "add"};
std::optional<Blend8Mode> parseBlend8Mode(std::string_view name);  //!< "alpha", "alpha-shift", ...
std::string_view blend8ModeName(Blend8Mode mode);

namespace blend8 {

//! Figures 1-2: (s*a + d*(255-a)) / 255, integer division (truncates).
inline std::uint8_t alpha(std::uint8_t s, std::uint8_t d, std::uint8_t a) {
    return std::uint8_t((s * a + d * (255 - a)) / 255);
}

//! Figure 3: the division by 255 replaced by a shift by 8 (so white over white gives 254).
inline std::uint8_t alphaShift(std::uint8_t s, std::uint8_t d, std::uint8_t a) {
    return std::uint8_t((s * a + d * (255 - a)) >> 8);
}

//! Figure 5: the source stored premultiplied, s' = s*a/255 (integer division).
inline std::uint8_t premultiply(std::uint8_t s, std::uint8_t a) {
    return std::uint8_t(s * a / 255);
}

//! Figure 6 with the stored inverse alpha ia = 255 - a: d = s' + ((d*ia) >> 8).
//! As printed, "source1_r + (source2_r * alpha) >> 8" parses in C as (s + d*ia) >> 8 because
//! + binds tighter than >>; the article's text (Figure 5's distributed sum) intends the shift
//! to apply to the destination term only, which is what this computes. The sum never exceeds
//! 255: s' <= a and (d*ia) >> 8 <= 255 - a.
inline std::uint8_t premultiplied(std::uint8_t sPremultiplied, std::uint8_t d,
                                  std::uint8_t inverseAlpha) {
    return std::uint8_t(sPremultiplied + ((d * inverseAlpha) >> 8));
}

//! Figure 7: saturating add with a 16-bit intermediate.
inline std::uint8_t add(std::uint8_t s, std::uint8_t d) {
    const std::uint16_t sum = std::uint16_t(s + d);
    return std::uint8_t(sum > 255 ? 255 : sum);
}

//! Figure 8's 512-entry table: alut[i] = min(i, 255).
const std::uint8_t* addLut();

// Saturating add over byte spans, out[i] = min(a[i] + b[i], 255); out may alias a or b.
// Three implementations that agree bit for bit; the SIMD one is what the tool uses.
void addSpanScalar16(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                     std::size_t n);
void addSpanLut(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n);
void addSpanSimd(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n);
//! "avx2", "sse2" or "scalar": the instruction set addSpanSimd picked on this CPU.
std::string_view addSimdIsa();

// Alpha modes over spans of pixels: src RGBA (straight alpha), dst with dstChannels (3 or 4)
// whose first three channels are blended in place; dst alpha is left as it is.
void alphaSpan(const std::uint8_t* srcRgba, std::uint8_t* dst, int dstChannels, std::size_t pixels);
void alphaShiftSpan(const std::uint8_t* srcRgba, std::uint8_t* dst, int dstChannels,
                    std::size_t pixels);
//! Converts straight RGBA to the Figure 5-6 storage: premultiplied RGB, inverse alpha in A.
void toPremultipliedInverse(const std::uint8_t* srcRgba, std::uint8_t* out, std::size_t pixels);
//! src is in the Figure 5-6 storage (see toPremultipliedInverse).
void premultipliedSpan(const std::uint8_t* srcPremulInverse, std::uint8_t* dst, int dstChannels,
                       std::size_t pixels);

}  // namespace blend8

//! Blends whole 8-bit images as `flarekit blend` does: src RGBA (RGB allowed for Add), dst RGB
//! or RGBA, same size; the result is RGB.
Result<Image8> blendImages8(Blend8Mode mode, const Image8& src, const Image8& dst);

// ---- float, linear light ----------------------------------------------------------------

enum class BlendMode {
    Add,     //!< dst += src: light adds (the default for flares; HDR-correct)
    Screen,  //!< dst = 1 - (1-dst)(1-src) per channel: the display-referred soft add
    Over,    //!< dst = src + dst*(1 - src.a): src premultiplied, Porter-Duff over
};
//! The modes' names, index = BlendMode value (presets, docs, messages).
inline constexpr std::array<std::string_view, 3> kBlendModeNames = {"add", "screen", "over"};
std::optional<BlendMode> parseBlendMode(std::string_view name);
std::string_view blendModeName(BlendMode mode);

//! Composites `n` premultiplied RGBA pixels of src onto dst in place. Alpha: Add keeps dst's,
//! Screen and Over combine as Porter-Duff over.
void compositeSpan(BlendMode mode, const float* src, float* dst, std::size_t n);

}  // namespace flarekit
