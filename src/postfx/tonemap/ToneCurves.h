// SPDX-License-Identifier: Apache-2.0
// The composite's display curve on one pixel: none, or a curve of src/core/ToneCurves.h on
// exposure x colour, alpha untouched. None leaves the values linear, scaled by the exposure
// (an 8-bit file then clips at 1; an EXR keeps them). Twin: shaders/tone_map.glsl.
#pragma once

#include "core/ToneCurves.h"
#include "flarekit/PostFx.h"
#include "postfx/Kernel.h"

namespace flarekit::postfx {

inline F4 toneMap(F4 c, int op, float exposure) {
    F4 out = c;
    if (op == int(ToneOperator::None)) {
        for (int i = 0; i < 3; ++i) out[i] = c[i] * exposure;
        return out;
    }
    for (int i = 0; i < 3; ++i) {
        const float x = std::max(0.f, c[i] * exposure);
        out[i] = op == int(ToneOperator::Aces) ? acesFitted(x) : hableFilmic(x);
    }
    return out;
}

}  // namespace flarekit::postfx
