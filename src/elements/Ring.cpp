// SPDX-License-Identifier: Apache-2.0
// Ring: "simply an antialiased circle of some dark color" (Tanczos 1999). An annulus whose outer
// edge is the element's rim, `width` wide, with a colour gradient across its width (inner
// colour at the inner edge), box-filtered over max(pixel, softness).
#include <cmath>

#include "elements/Coverage.h"
#include "elements/ElementKernel.h"

namespace flarekit {

Rgba shadeRing(const ElementKernel& k, float x, float y) {
    const float d = std::sqrt(x * x + y * y);
    const float filter = std::max(k.pixel, k.params.softness);
    const float outerEdge = 1.f - 0.5f * (filter - k.pixel);  // blur stays inside the rim
    const float innerEdge = outerEdge - k.params.width;
    const float cover = coverage::interval(d, innerEdge, outerEdge, filter);
    return gradient(k, std::clamp((d - innerEdge) / k.params.width, 0.f, 1.f), cover);
}

}  // namespace flarekit
