// SPDX-License-Identifier: Apache-2.0
// Bright pass: the input, filtered to half resolution (one bilinear tap at the output pixel's
// centre is the 2x2 box of an even-sized input), through a soft-knee threshold. The curve is
// the one Unity's post-processing stack uses for its bloom prefilter: zero below
// threshold - knee, a quadratic ease-in up to threshold + knee, then colour x (br - T) / br, so
// above the knee the output grows linearly with the light's value above the threshold (what
// the energy test asserts). NaN, Inf and negative input pixels read as 0. The seed's own threshold
// (0.1) is the ghosts' one. Twin: shaders/bright_pass.frag.
#pragma once

#include "postfx/Kernel.h"

namespace flarekit::postfx {

struct BrightUniforms {
    float threshold = 1.f, knee = 0.5f, ceiling = 0.f;
    Vec2 invOutSize;
};

//! Smallest denominators, so black pixels and knee = 0 divide safely.
inline constexpr float kBrightEpsilon = 1e-5f;

inline F4 softThreshold(F4 color, float threshold, float knee) {
    const float brightness = std::max(color[0], std::max(color[1], color[2]));
    float soft = std::clamp(brightness - threshold + knee, 0.f, 2.f * knee);
    soft = soft * soft / (4.f * knee + kBrightEpsilon);
    const float weight =
        std::max(soft, brightness - threshold) / std::max(brightness, kBrightEpsilon);
    return rgbOnly(color * weight);
}

//! Highlight compression: brightness b (the largest channel) becomes C tanh(b / C), hue kept;
//! tanh written with exp so both twins evaluate the same expression.
inline F4 compressHighlights(F4 color, float ceiling) {
    if (ceiling <= 0.f) return color;
    const float brightness = std::max(color[0], std::max(color[1], color[2]));
    const float e = std::exp(-2.f * brightness / ceiling);
    const float compressed = ceiling * (1.f - e) / (1.f + e);
    return color * (compressed / std::max(brightness, kBrightEpsilon));
}

inline F4 brightPixel(const BrightUniforms& u, const Tex& input, int x, int y) {
    const F4 color =
        compressHighlights(bilinearLight(input, pixelUv(x, y, u.invOutSize)), u.ceiling);
    return softThreshold(color, u.threshold, u.knee);
}

//! The pass unit: its pixel over the chain's inputs (the input image) and its uniforms by the
//! names bright_pass.frag declares.
inline F4 passPixel(const BrightUniforms& u, const Tex* in, int x, int y) {
    return brightPixel(u, in[0], x, y);
}
template <class Sink>
void bindUniforms(const BrightUniforms& u, Sink& s) {
    s.set("threshold", u.threshold), s.set("knee", u.knee), s.set("ceiling", u.ceiling),
        s.set("invOutSize", u.invOutSize);
}

}  // namespace flarekit::postfx
