// SPDX-License-Identifier: Apache-2.0
// Polygonal iris ghost: the shape of an N-blade aperture that modern engines give their
// ghosts. A regular N-gon with circumradius 1 (vertices on the rim): the distance to the
// nearest edge along its normal is d*cos(phi) - cos(pi/N), phi the angle to that normal.
#include <cmath>
#include <numbers>

#include "core/FastMath.h"
#include "elements/Coverage.h"
#include "elements/ElementKernel.h"

namespace flarekit {

Rgba shadePolygon(const ElementKernel& k, float x, float y) {
    const float d = std::sqrt(x * x + y * y);
    const float sector = 2.f * std::numbers::pi_v<float> / float(k.params.blades);
    const float theta = fastAtan2(y, x);
    const float phi =
        theta - sector * std::round(theta / sector);  // angle to the nearest edge normal
    const float apothem = std::cos(0.5f * sector);
    const float filter = std::max(k.pixel, k.params.softness);
    const float edge = apothem - 0.5f * (filter - k.pixel);
    return gradient(k, std::min(d, 1.f), coverage::below(d * std::cos(phi), edge, filter));
}

}  // namespace flarekit
