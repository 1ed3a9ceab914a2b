// SPDX-License-Identifier: Apache-2.0
// A second way to place ghosts: a paraxial y-u trace of each ghost path, clipped by the clear
// apertures as circles. Lens.GhostCentresAgreeWithAParaxialTraceAtSmallAngles (1 degree, every
// run) and LensGhostSweep.ParaxialTableAt1To20Degrees (label slow) compare `lens ghosts` with it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "flarekit/Lens.h"

namespace paraxialref {

using namespace flarekit;

//! The second implementation: a paraxial y-u trace of one ghost path in the meridional plane
//! with signed indices (negative after each reflection), giving the linear map from the
//! entrance height y0 and slope u0 to the height at every surface and at the sensor.
struct Linear {
    double a = 0, b = 0;  // y = a y0 + b u0
};
struct ParaxialPath {
    std::vector<Linear> atSurface;  // each interaction, in path order
    std::vector<int> surface;
    Linear sensor;
};

inline ParaxialPath paraxialGhost(const Lens& lens, int first, int second) {
    std::vector<std::pair<int, bool>> steps;  // surface, reflect
    const int n = int(lens.surfaces.size());
    if (first < 0) {
        for (int k = 0; k < n; ++k) steps.push_back({k, false});
    } else {
        for (int k = 0; k < first; ++k) steps.push_back({k, false});
        steps.push_back({first, true});
        for (int k = first - 1; k > second; --k) steps.push_back({k, false});
        steps.push_back({second, true});
        for (int k = second + 1; k < n; ++k) steps.push_back({k, false});
    }
    std::vector<double> z{0};
    for (const LensSurface& s : lens.surfaces) z.push_back(z.back() + s.thickness);
    const auto index = [&](int k) { return k < 0 ? 1.0 : lens.surfaces[std::size_t(k)].nd; };
    ParaxialPath p;
    // Two rays: (y0, u0) = (1, 0) and (0, 1), carried together.
    double y[2] = {1, 0}, u[2] = {0, 1}, zc = 0, dir = 1;
    for (const auto& [k, reflect] : steps) {
        for (int r = 0; r < 2; ++r) y[r] += u[r] * (z[std::size_t(k)] - zc);
        zc = z[std::size_t(k)];
        p.atSurface.push_back({y[0], y[1]});
        p.surface.push_back(k);
        const LensSurface& s = lens.surfaces[std::size_t(k)];
        const double c = s.radius == 0 ? 0 : 1 / s.radius;
        const double nHere = dir > 0 ? index(k - 1) : index(k);
        const double nOther = dir > 0 ? index(k) : index(k - 1);
        const double from = dir * nHere;
        const double to = reflect ? -from : dir * nOther;
        for (int r = 0; r < 2; ++r) u[r] = (from * u[r] - y[r] * (to - from) * c) / to;
        if (reflect) dir = -dir;
    }
    for (int r = 0; r < 2; ++r) y[r] += u[r] * (z.back() - zc);
    p.sensor = {y[0], y[1]};
    return p;
}

//! The paraxial ghost's centroid (x only; the field is along x) over the entrance points that
//! pass every clear aperture, on a fine grid.
inline bool paraxialCentroid(const Lens& lens, const ParaxialPath& p, double tanX, double& cx,
                             double& share) {
    const double sa = lens.surfaces.front().semiAperture;
    constexpr int kGrid = 300;
    double sum = 0;
    int count = 0;
    for (int iy = 0; iy < kGrid; ++iy) {
        for (int ix = 0; ix < kGrid; ++ix) {
            const double x = sa * (2.0 * (ix + 0.5) / kGrid - 1),
                         y = sa * (2.0 * (iy + 0.5) / kGrid - 1);
            bool pass = true;
            for (std::size_t k = 0; k < p.atSurface.size() && pass; ++k) {
                const double hx = p.atSurface[k].a * x + p.atSurface[k].b * tanX;
                const double hy = p.atSurface[k].a * y;
                const double clear = lens.surfaces[std::size_t(p.surface[k])].semiAperture;
                pass = hx * hx + hy * hy <= clear * clear;  // (glibc's hypot is slow)
            }
            if (!pass) continue;
            sum += p.sensor.a * x + p.sensor.b * tanX;
            ++count;
        }
    }
    if (count < 50) return false;
    cx = sum / count;
    share = double(count) / (kGrid * kGrid * M_PI / 4);
    return true;
}

//! Every shipped lens at each of `degrees`: the compared ghosts' largest centroid difference as
//! a share of the diagonal (printed: docs/lens.md's table). At 1 degree every compared ghost is
//! within 1%, but for one known case of the telephoto zoom under 1.5%.
inline int compareWithParaxial(const std::vector<double>& degrees) {
    int total = 0;
    for (const std::string& name : lensNames()) {
        auto loaded = loadLens(name);
        EXPECT_TRUE(loaded.ok()) << name;
        if (!loaded.ok()) continue;
        Lens lens = *loaded;
        lens.aperture.blades = 0;  // the paraxial reference clips with circles
        const double diagonal = std::hypot(lens.sensor.width, lens.sensor.height);
        for (const double deg : degrees) {
            GhostQuery q;
            q.angleXDeg = deg;
            q.ghostRays = 0;  // compact ghosts: the 64-ray grid places them to 0.1%
            auto r = analyseGhosts(lens, q);
            if (!r.ok()) continue;
            double worst = 0;
            int compared = 0;
            // The ghosts that are images of the aperture (not washes over several frames),
            // vignetted alike in both traces: where a centroid means the same thing.
            for (const GhostFigure& g : r->ghosts) {
                // Whole on the sensor: the paraxial centroid is of every ray.
                if (g.rays < 50 || g.radius > 0.25 * diagonal || g.onSensor < 1) continue;
                const ParaxialPath p = paraxialGhost(lens, g.first, g.second);
                double cx = 0, share = 0;
                if (!paraxialCentroid(lens, p, std::tan(deg * M_PI / 180), cx, share)) continue;
                if (std::fabs(share - g.beamShare) > 0.05 * g.beamShare) continue;
                const double d = std::fabs(cx - g.centerX) / diagonal;
                worst = std::max(worst, d);
                ++compared;
                if (deg == 1.0) {
                    // One known case: a ghost of the telephoto zoom position sits at 1.07% (its
                    // exact beam carries coma the paraxial one cannot); nothing else passes 1%.
                    EXPECT_LT(d, 0.015) << name << " ghost " << g.first << "," << g.second;
                }
            }
            std::printf(
                "paraxial check %-24s %4.0f deg: %3d ghosts, largest centre difference %.4f of the "
                "diagonal\n",
                name.c_str(), deg, compared, worst);
            total += compared;
        }
    }
    return total;
}

}  // namespace paraxialref
