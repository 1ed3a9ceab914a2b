// SPDX-License-Identifier: Apache-2.0
// One step of the downsample chain: Jorge Jimenez's 13-tap filter ("Next Generation Post
// Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014). Five overlapping 2x2 boxes
// (four corner boxes weighted 1/8 each, the centre box 1/2), each one bilinear tap apart, so a
// single bright texel moving across the screen does not flicker the way a plain 2x2 box chain
// aliases. Twin: shaders/downsample.frag.
#pragma once

#include "postfx/Kernel.h"

namespace flarekit::postfx {

struct DownsampleUniforms {
    Vec2 invOutSize;  //!< 1 / destination size
    Vec2 srcTexel;    //!< 1 / source size: one source texel in normalised units
};

inline F4 downsamplePixel(const DownsampleUniforms& u, const Tex& src, int x, int y) {
    const Vec2 uv = pixelUv(x, y, u.invOutSize);
    const auto at = [&](float dx, float dy) {
        return bilinear(src, {uv.x + dx * u.srcTexel.x, uv.y + dy * u.srcTexel.y});
    };
    const F4 a = at(-2, -2), b = at(0, -2), c = at(2, -2);
    const F4 d = at(-2, 0), e = at(0, 0), f = at(2, 0);
    const F4 g = at(-2, 2), h = at(0, 2), i = at(2, 2);
    const F4 j = at(-1, -1), k = at(1, -1), l = at(-1, 1), m = at(1, 1);
    return e * 0.125f + (a + c + g + i) * 0.03125f + (b + d + f + h) * 0.0625f +
           (j + k + l + m) * 0.125f;
}

//! The pass unit: its pixel over the finer level and its uniforms by downsample.frag's names.
inline F4 passPixel(const DownsampleUniforms& u, const Tex* in, int x, int y) {
    return downsamplePixel(u, in[0], x, y);
}
template <class Sink>
void bindUniforms(const DownsampleUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("srcTexel", u.srcTexel);
}

}  // namespace flarekit::postfx
