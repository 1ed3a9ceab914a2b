// SPDX-License-Identifier: Apache-2.0
// How much of a light's disc a matte or depth pass leaves visible: the area-weighted mean of
// each pixel's visibility over the disc, so a foreground covering a third of the sun dims its
// flare by a third.
#include <algorithm>
#include <cmath>

#include "flarekit/Shot.h"

namespace flarekit {

namespace {
//! Sub-samples per side in a pixel the disc's rim crosses: 256 samples put a pixel's share of
//! the disc within 1/256 of its area, far under the 0.01 a coverage is held to even for a disc
//! of radius 1 px (whose rim crosses about 8 pixels, errors partly cancelling).
constexpr int kRimSamples = 16;

float pixelVisibility(const Rgba& p, const Occluder& o) {
    const float v = o.channel == 0 ? p.r : o.channel == 1 ? p.g : o.channel == 2 ? p.b : p.a;
    if (o.lightDepth) return v >= *o.lightDepth ? 1.f : 0.f;
    return 1.f - std::clamp(v, 0.f, 1.f);
}
}  // namespace

double discVisibility(const Image& image, const Occluder& occluder, Point centre, double radius) {
    const int w = image.width(), h = image.height();
    // A disc wholly outside the frame (a light far off it, even at 1e30 px) is visible; what
    // remains is near enough for the int casts below.
    if (!(centre.x + radius > 0 && centre.x - radius < w && centre.y + radius > 0 &&
          centre.y - radius < h))
        return 1;
    if (radius < 0.5) {
        const int x = int(std::floor(centre.x)), y = int(std::floor(centre.y));
        if (x < 0 || y < 0 || x >= w || y >= h) return 1;
        return pixelVisibility(image.at(x, y), occluder);
    }
    const double cx = centre.x, cy = centre.y, r2 = radius * radius;
    const int x0 = std::max(0, int(std::floor(cx - radius))),
              x1 = std::min(w - 1, int(std::floor(cx + radius)));
    const int y0 = std::max(0, int(std::floor(cy - radius))),
              y1 = std::min(h - 1, int(std::floor(cy + radius)));
    double weighted = 0, area = 0;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            // Nearest and farthest points of the pixel square [x, x+1] x [y, y+1] from the centre.
            const double nx = std::clamp(cx, double(x), double(x + 1)) - cx,
                         ny = std::clamp(cy, double(y), double(y + 1)) - cy;
            const double fx = std::max(std::abs(x - cx), std::abs(x + 1 - cx)),
                         fy = std::max(std::abs(y - cy), std::abs(y + 1 - cy));
            double inside;
            if (nx * nx + ny * ny >= r2) {
                continue;  // wholly outside
            } else if (fx * fx + fy * fy <= r2) {
                inside = 1;
            } else {
                int hits = 0;
                for (int j = 0; j < kRimSamples; ++j)
                    for (int i = 0; i < kRimSamples; ++i) {
                        const double sx = x + (i + 0.5) / kRimSamples - cx,
                                     sy = y + (j + 0.5) / kRimSamples - cy;
                        hits += sx * sx + sy * sy < r2;
                    }
                inside = double(hits) / (kRimSamples * kRimSamples);
            }
            weighted += inside * pixelVisibility(image.at(x, y), occluder);
            area += inside;
        }
    }
    return area > 0 ? weighted / area : 1.0;
}

}  // namespace flarekit
