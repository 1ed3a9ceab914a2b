// The lens buffer, at the working (1/4) resolution: everything the chain adds to the image.
//   flare = chromatic(ghosts + halo) x starburst + streaks
//   lens  = (bloom x bloomIntensity + flare) x (1 + dirtIntensity x dirt)
// The seed's CombinePS is the sum bloom + pass 1 + pass 2; dirt and starburst are 1 and
// chromatic is the identity when they are off. Twin: shaders/lens.frag.
#pragma once

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
    const F4 flare = chromaticFlare(in.ghosts, in.halo, uv, u.chromatic) * starburstModulation(u.star, uv, u.aspect) +
                     in.streaks.texel(x, y);
    F4 lens = in.bloom.texel(x, y) * u.bloomIntensity + flare;
    if (u.dirtIntensity > 0.f) lens = lens * (1.f + u.dirtIntensity * in.dirt.texel(x, y)[0]);
    return rgbOnly(lens);
}

}  // namespace flarekit::postfx
