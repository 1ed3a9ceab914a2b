// Display curves for 8-bit outputs, applied per channel to exposure x colour (alpha untouched):
// - aces: Krzysztof Narkowicz's fit of the ACES filmic curve (2015), as tonemapAcesFitted;
// - filmic: John Hable's Uncharted 2 curve (GDC 2010, "Filmic Tonemapping Operators") with
//   his constants A..F, white point W = 11.2 and exposure bias 2.
// None leaves the values linear (an 8-bit file then clips at 1). Twin: shaders/tone_curves.glsl.
#pragma once

#include "flarekit/PostFx.h"
#include "postfx/Kernel.h"

namespace flarekit::postfx {

inline float acesFitted(float x) {
    return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.f, 1.f);
}

inline float hablePartial(float x) {
    const float a = 0.15f, b = 0.50f, c = 0.10f, d = 0.20f, e = 0.02f, f = 0.30f;
    return (x * (a * x + c * b) + d * e) / (x * (a * x + b) + d * f) - e / f;
}

inline float hableFilmic(float x) {
    const float kWhite = 11.2f, kExposureBias = 2.f;
    return std::clamp(hablePartial(x * kExposureBias) / hablePartial(kWhite), 0.f, 1.f);
}

inline F4 toneMap(F4 c, int op, float exposure) {
    if (op == int(ToneOperator::None)) return c;
    F4 out = c;
    for (int i = 0; i < 3; ++i) {
        const float x = std::max(0.f, c[i] * exposure);
        out[i] = op == int(ToneOperator::Aces) ? acesFitted(x) : hableFilmic(x);
    }
    return out;
}

}  // namespace flarekit::postfx
