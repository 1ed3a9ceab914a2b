// The one full-resolution pass after the bright pass: the input plus the lens buffer,
// upsampled bilinearly, then the optional display curve. Alpha is the input's, untouched.
// Twin: shaders/composite.frag.
#pragma once

#include "postfx/Kernel.h"
#include "postfx/tonemap/ToneCurves.h"

namespace flarekit::postfx {

struct CompositeUniforms {
    Vec2 invOutSize;
    int toneOperator = 0;
    float exposure = 1.f;
};

inline F4 compositePixel(const CompositeUniforms& u, const Tex& input, const Tex& lens, int x, int y) {
    const F4 color = input.texel(x, y) + rgbOnly(bilinear(lens, pixelUv(x, y, u.invOutSize)));
    return toneMap(color, u.toneOperator, u.exposure);
}

}  // namespace flarekit::postfx
