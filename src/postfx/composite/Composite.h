// SPDX-License-Identifier: Apache-2.0
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

//! The CPU's draw of the whole pass: compositePixel on every pixel, bit for bit (tested), with
//! the lens buffer's upsample filtered separably (BilinearRows). The composite is the one pass
//! at full resolution, where the per-pixel bilinear tap was most of its cost.
inline void drawPass(const CompositeUniforms& u, const Tex* in, Image& out) {
    const Tex input = in[0];
    const BilinearColumns columns(in[1], out.width(), u.invOutSize);
    runUpsamplePass(out, columns, [&](int x, int y, F4 lens) {
        return toneMap(input.texel(x, y) + rgbOnly(lens), u.toneOperator, u.exposure);
    });
}
template <class Sink>
void bindUniforms(const CompositeUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("toneOperator", u.toneOperator),
        s.set("exposure", u.exposure);
}

}  // namespace flarekit::postfx
