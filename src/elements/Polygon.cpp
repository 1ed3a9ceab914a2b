// SPDX-License-Identifier: Apache-2.0
// Polygonal iris ghost: the shape of an N-blade aperture that modern engines give their
// ghosts. A regular N-gon with circumradius 1 (vertices on the rim): the distance to the
// nearest edge along its normal is d*cos(phi) - cos(pi/N), phi the angle to that normal.
// Rounded corners (roundness r) are the Minkowski sum of the polygon of apothem (1 - r) cos(pi/N)
// and a disc of radius r cos(pi/N), as Unity's SDF polygon rounds them.
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
    // Distance along the edge normal; with rounding, the inner polygon (apothem shrunk by
    // roundness) plus the Euclidean distance to it past its corner, so the corner is an arc.
    float along = d * std::cos(phi);
    if (k.params.roundness > 0.f) {
        const float inner = apothem * (1.f - k.params.roundness);
        const float halfSide = inner * std::tan(0.5f * sector);
        const float across = std::abs(d * std::sin(phi)) - halfSide;
        if (across > 0.f) along = inner + std::hypot(std::max(along - inner, 0.f), across);
    }
    return gradient(k, std::min(d, 1.f), coverage::below(along, edge, filter));
}

}  // namespace flarekit
