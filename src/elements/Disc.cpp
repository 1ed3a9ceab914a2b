// SPDX-License-Identifier: Apache-2.0
// Secondary disc (Tanczos 1999, Figure 11): "a ring of any color, smoothly transition to another
// color using smaller and smaller rings until your final ring has a radius of 0", blurred.
// The colour runs linearly from innerColor at the centre to color at the rim; the edge is
// box-filtered over max(pixel, softness) (the seed's blur), kept inside the rim.
#include <cmath>

#include "elements/Coverage.h"
#include "elements/ElementKernel.h"

namespace flarekit {

Rgba shadeDisc(const ElementKernel& k, float x, float y) {
    const float d = std::sqrt(x * x + y * y);
    const float filter = std::max(k.pixel, k.params.softness);
    const float edge = 1.f - 0.5f * (filter - k.pixel);
    return gradient(k, std::min(d, 1.f), coverage::below(d, edge, filter));
}

}  // namespace flarekit
