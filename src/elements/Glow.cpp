// SPDX-License-Identifier: Apache-2.0
// Glow: the main flare's soft core. Falloff from Tanczos 1999 ("Parts of a Flare"):
//     Intensity = exp(-i*i*0.006)*0.50 + exp(-i*0.03)*(1-0.50)
// with i in pixels of a sprite of about 128 pixels' radius. To keep that shape at any size,
// i is the distance scaled so the rim (d = 1) is i = 128, and the curve is shifted and
// rescaled so it reaches exactly 0 at the rim (the seed's curve is still 1.1% there):
//     g(d) = (f(128 d) - f(128)) / (1 - f(128)).
#include <algorithm>
#include <cmath>

#include "elements/ElementKernel.h"

namespace flarekit {

namespace {
//! The seed's reference radius in pixels (see the file comment).
constexpr float kSeedRadius = 128.f;

float seedFalloff(float i) {
    return std::exp(-i * i * 0.006f) * 0.5f + std::exp(-i * 0.03f) * 0.5f;
}
}  // namespace

float glowProfile(float d) {
    static const float rim = seedFalloff(kSeedRadius);
    if (d >= 1.f) return 0.f;
    return std::max(0.f, (seedFalloff(kSeedRadius * d) - rim) / (1.f - rim));
}

Rgba shadeGlow(const ElementKernel& k, float x, float y) {
    const float d = std::sqrt(x * x + y * y);
    return gradient(k, d, glowProfile(d));
}

}  // namespace flarekit
