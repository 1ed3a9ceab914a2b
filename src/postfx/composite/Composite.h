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

inline F4 compositePixel(const CompositeUniforms& u, const Tex& input, const Tex& lens, int x,
                         int y) {
    const F4 color = input.texel(x, y) + rgbOnly(bilinear(lens, pixelUv(x, y, u.invOutSize)));
    return toneMap(color, u.toneOperator, u.exposure);
}

//! The pass unit: its pixel over (input, lens buffer) and its uniforms by composite.frag's names.
inline F4 passPixel(const CompositeUniforms& u, const Tex* in, int x, int y) {
    return compositePixel(u, in[0], in[1], x, y);
}
template <class Sink>
void bindUniforms(const CompositeUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("toneOperator", u.toneOperator),
        s.set("exposure", u.exposure);
}

}  // namespace flarekit::postfx
