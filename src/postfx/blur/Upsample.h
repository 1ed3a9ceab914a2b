// SPDX-License-Identifier: Apache-2.0
// The blur of the bloom buffer: the progressive upsample of the dual filter (Jimenez 2014;
// Marius Bjorge, "Bandwidth-Efficient Rendering", SIGGRAPH 2015). Each level adds a 3x3 tent
// of the coarser (already blurred) level, one coarse texel apart, to its own downsample:
//   U(k) = D(k) + spread * tent(U(k+1)),   bloom = U(2) * norm,
// where norm = 1 / (1 + spread + spread^2 + ...) makes a flat field come out flat, so the
// bloom is a mean-preserving blur whose radius grows with `levels`. Twin: shaders/upsample.frag.
#pragma once

#include "postfx/Kernel.h"

namespace flarekit::postfx {

struct UpsampleUniforms {
    Vec2 invOutSize;
    Vec2 coarseTexel;  //!< 1 / coarse size
    float spread = 1.f;
    float scale = 1.f;  //!< 1, or norm on the last step
};

inline F4 upsamplePixel(const UpsampleUniforms& u, const Tex& fine, const Tex& coarse, int x,
                        int y) {
    const Vec2 uv = pixelUv(x, y, u.invOutSize);
    const auto at = [&](float dx, float dy) {
        return bilinear(coarse, {uv.x + dx * u.coarseTexel.x, uv.y + dy * u.coarseTexel.y});
    };
    const F4 corners = at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1);
    const F4 edges = at(0, -1) + at(-1, 0) + at(1, 0) + at(0, 1);
    const F4 tent = (corners + edges * 2.f + at(0, 0) * 4.f) * 0.0625f;
    return (fine.texel(x, y) + tent * u.spread) * u.scale;
}

//! The pass unit: its pixel over (the level's downsample, the coarser upsample) and its
//! uniforms by upsample.frag's names.
inline F4 passPixel(const UpsampleUniforms& u, const Tex* in, int x, int y) {
    return upsamplePixel(u, in[0], in[1], x, y);
}
template <class Sink>
void bindUniforms(const UpsampleUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("coarseTexel", u.coarseTexel),
        s.set("spread", u.spread), s.set("scale", u.scale);
}

}  // namespace flarekit::postfx
