// SPDX-License-Identifier: Apache-2.0
#include "engine/TileChoice.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flarekit::engine {

namespace {
//! The light's radius on screen in pixels of the frame's viewport, as light_coverage.comp
//! reckons it (tan of its half-angle, at most 1.4 rad, times the projection's y scale), or
//! -1 when the camera is inside a sphere light.
double radiusPixels(const fk_frame& f, const fk_light& l) {
    double half = double(l.radius) * std::numbers::pi / 180.0;
    if (l.type == FK_LIGHT_POINT) {
        double centre[3];
        for (int r = 0; r < 3; ++r)
            centre[r] = double(f.view[r]) * l.position[0] + double(f.view[4 + r]) * l.position[1] +
                        double(f.view[8 + r]) * l.position[2] + double(f.view[12 + r]);
        const double distance = std::hypot(centre[0], centre[1], centre[2]);
        if (distance <= l.radius) return -1;
        half = std::asin(double(l.radius) / distance);
    }
    return std::tan(std::min(half, 1.4)) * std::abs(f.projection[5]) * 0.5 * f.viewport[3];
}
}  // namespace

int chooseTiles(const fk_frame& f, int depthSamples, const fk_light* lights, int count, bool every,
                int belowSamples, std::vector<int>& tileOf) {
    tileOf.assign(std::size_t(count), -1);
    int tiled = 0;
    for (int i = 0; i < count; ++i) {
        const double r = radiusPixels(f, lights[i]);
        const double footprint = std::numbers::pi * r * r * depthSamples;
        if (every || (r >= 0 && footprint < belowSamples)) tileOf[std::size_t(i)] = tiled++;
    }
    return tiled;
}

}  // namespace flarekit::engine
