// SPDX-License-Identifier: Apache-2.0
// The display curves, once for every path (the sprite/scene tone map, the GPU tone map, the
// postfx composite), applied per channel to exposure x colour:
// - aces: Krzysztof Narkowicz's fit of the ACES filmic curve ("ACES Filmic Tone Mapping
//   Curve", 2015);
// - filmic: John Hable's Uncharted 2 curve (GDC 2010, "Filmic Tonemapping Operators") with
//   his constants A..F, white point W = 11.2 and exposure bias 2.
// Twin: shaders/tone_curves.glsl, line for line.
#pragma once

#include <algorithm>

namespace flarekit {

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

}  // namespace flarekit
