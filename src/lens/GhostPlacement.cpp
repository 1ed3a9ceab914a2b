// SPDX-License-Identifier: Apache-2.0
#include "lens/GhostPlacement.h"

#include <cmath>

#include "lens/GhostMesh.h"

namespace flarekit {

namespace lens {

std::array<double, 2> fieldAngle(const TraceLens& t, double focal, double x, double y) {
    double tx = x / focal, ty = y / focal;
    const auto path = lens::ghostPath(int(t.surfaces.size()), -1, -1);
    const double sa = t.surfaces.front().semiAperture;
    for (int iter = 0; iter < 2; ++iter) {
        const lens::Vec dir =
            lens::beamDirection(std::atan(tx) * 180 / M_PI, std::atan(ty) * 180 / M_PI);
        double cx = 0, cy = 0;
        int n = 0;
        for (int k = 0; k < 64; ++k) {
            const double gx = sa * (2.0 * ((k % 8) + 0.5) / 8 - 1),
                         gy = sa * (2.0 * ((k / 8) + 0.5) / 8 - 1);
            const RayResult r =
                lens::traceRay(t, path, lens::beamOrigin(t, dir, gx, gy), dir, true);
            if (r.alive) cx += r.x, cy += r.y, ++n;
        }
        if (n == 0) break;
        cx /= n, cy /= n;
        if (std::fabs(cx) > 1e-9) tx *= x / cx;
        if (std::fabs(cy) > 1e-9) ty *= y / cy;
    }
    return {std::atan(tx) * 180 / M_PI, std::atan(ty) * 180 / M_PI};
}

PickedGhosts pickGhosts(const Lens& lens, std::array<double, 2> angle, int count) {
    PickedGhosts out;
    if (count <= 0) return out;
    GhostQuery q;
    q.angleXDeg = angle[0], q.angleYDeg = angle[1], q.gridSide = 16;
    q.ghostRays = 0;  // the intensities only: positions are drawn from the meshes
    auto report = analyseGhosts(lens, q);
    if (!report) return out;
    for (const GhostFigure& g : report->ghosts) {
        if (int(out.pairs.size()) >= count) break;
        if (g.intensity[0] + g.intensity[1] + g.intensity[2] <= 0) continue;
        out.pairs.push_back({g.first, g.second});
        // Rec. 709 luminance, in double: the shares run down to 1e-9.
        out.share = std::max(
            out.share, 0.2126 * g.intensity[0] + 0.7152 * g.intensity[1] + 0.0722 * g.intensity[2]);
    }
    return out;
}

}  // namespace lens

Result<std::vector<GhostOnImage>> ghostsOnImage(const Lens& lens, int width, int height,
                                                Point light, int count) {
    if (width < 1 || height < 1) return invalidInput("ghosts on image: an empty image");
    flarekit::lens::SensorMap map;
    map.width = width, map.height = height;
    map.mmPerPixel = std::min(lens.sensor.width / width, lens.sensor.height / height);
    const flarekit::lens::TraceLens dLine = flarekit::lens::prepareTrace(lens, kLineD);
    const auto angle = flarekit::lens::fieldAngle(dLine, paraxial(lens).focalLength,
                                                  map.toMmX(light.x), map.toMmY(light.y));
    // The ghosts the render draws (pickGhosts' order), placed by the refined analysis.
    const flarekit::lens::PickedGhosts picked = flarekit::lens::pickGhosts(lens, angle, count);
    GhostQuery q;
    q.angleXDeg = angle[0], q.angleYDeg = angle[1];
    auto report = analyseGhosts(lens, q);
    if (!report) return report.error();
    std::vector<GhostOnImage> out;
    for (const auto& [first, second] : picked.pairs) {
        for (const GhostFigure& g : report->ghosts) {
            if (g.first != first || g.second != second) continue;
            out.push_back({g.first, g.second, map.toPxX(g.centerX), map.toPxY(g.centerY),
                           g.radius90 / map.mmPerPixel, g.intensity});
            break;
        }
    }
    return out;
}

}  // namespace flarekit
