// SPDX-License-Identifier: Apache-2.0
// The lens buffer, at the working (1/4) resolution: everything the chain adds to the image.
//   flare = chromatic(ghosts + halo) x starburst + streaks
//   lens  = (bloom x bloomIntensity + flare) x (1 + dirtIntensity x dirt)
// The seed's CombinePS is the sum bloom + pass 1 + pass 2; dirt and starburst are 1 and
// chromatic is the identity when they are off. Twin: shaders/lens.frag.
#pragma once

#include <span>
#include <string>
#include "postfx/Kernel.h"
#include "postfx/chromatic/Chromatic.h"
#include "postfx/starburst/Starburst.h"

namespace flarekit::postfx {

struct LensUniforms {
    Vec2 invOutSize;
    float aspect = 1.f;
    float bloomIntensity = 0.f;
    float chromatic = 0.f;
    float dirtIntensity = 0.f;
    StarburstUniforms star;
};

struct LensInputs {
    Tex bloom, ghosts, halo, streaks, dirt;
};

inline F4 lensPixel(const LensUniforms& u, const LensInputs& in, int x, int y) {
    const Vec2 uv = pixelUv(x, y, u.invOutSize);
    const F4 flare = chromaticFlare(in.ghosts, in.halo, uv, u.chromatic) *
                         starburstModulation(u.star, uv, u.aspect) +
                     in.streaks.texel(x, y);
    F4 lens = in.bloom.texel(x, y) * u.bloomIntensity + flare;
    if (u.dirtIntensity > 0.f) lens = lens * (1.f + u.dirtIntensity * in.dirt.texel(x, y)[0]);
    return rgbOnly(lens);
}

//! The pass unit: its pixel over (bloom, ghosts, halo, streaks, dirt) and its uniforms by
//! lens.frag's (and starburst.glsl's) names.
inline F4 passPixel(const LensUniforms& u, const Tex* in, int x, int y) {
    return lensPixel(u, LensInputs{in[0], in[1], in[2], in[3], in[4]}, x, y);
}
template <class Sink>
void bindUniforms(const LensUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("aspect", u.aspect),
        s.set("bloomIntensity", u.bloomIntensity);
    s.set("chromatic", u.chromatic), s.set("dirtIntensity", u.dirtIntensity);
    s.set("starIntensity", u.star.intensity), s.set("starWidth", u.star.width),
        s.set("starSpokes", u.star.spokes);
    s.set("starRays", std::span<const float>(u.star.rays));
    s.set("starCentreCount", u.star.centreCount);
    s.set("starCentres", std::span<const Vec2>(u.star.centres));
}

}  // namespace flarekit::postfx
