// SPDX-License-Identifier: Apache-2.0
// Lateral chromatic aberration of the flare (ghosts + halo): red is read at (1 + amount) times
// the pixel's distance from the centre, blue at (1 - amount), green in place, so a ghost splits
// into a red-outside / blue-inside fringe the way a lens with lateral colour spreads it.
// Twin: shaders/chromatic.glsl.
#pragma once

#include "postfx/Kernel.h"

namespace flarekit::postfx {

inline F4 flareAt(const Tex& ghosts, const Tex& halo, Vec2 uv) {
    return bilinear(ghosts, uv) + bilinear(halo, uv);
}

inline F4 chromaticFlare(const Tex& ghosts, const Tex& halo, Vec2 uv, float amount) {
    if (amount == 0.f) return flareAt(ghosts, halo, uv);
    const Vec2 d{uv.x - 0.5f, uv.y - 0.5f};
    const float red =
        flareAt(ghosts, halo, {0.5f + d.x * (1.f + amount), 0.5f + d.y * (1.f + amount)})[0];
    const float green = flareAt(ghosts, halo, uv)[1];
    const float blue =
        flareAt(ghosts, halo, {0.5f + d.x * (1.f - amount), 0.5f + d.y * (1.f - amount)})[2];
    return F4{red, green, blue, 0.f};
}

}  // namespace flarekit::postfx
