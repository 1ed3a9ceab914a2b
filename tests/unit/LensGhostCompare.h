// SPDX-License-Identifier: Apache-2.0
// `lens ghosts` against the second tracer (LensReferenceTracer.h), ghost by ghost: the checks
// LensGhostAccuracyTest.cpp runs on three lenses and LensGhostSweepTest.cpp on every one.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "LensReferenceTracer.h"
#include "ShippedLens.h"
#include "flarekit/Lens.h"

namespace lensghosts {

using namespace flarekit;

using test::parsedLens;
using test::shippedLens;

inline double diagonal(const Lens& lens) {
    return std::hypot(lens.sensor.width, lens.sensor.height);
}

struct Agreement {
    double worst = 0;       //!< largest centre difference over the diagonal
    int compared = 0;       //!< ghosts compared
    int missing = 0;        //!< ghosts over 5% of the light that flarekit lacks
    double worstShare = 0;  //!< largest share difference
};

//! Every ghost flarekit reports at the angle that carries 1% or more of the entering light and
//! fits on the sensor (most of its rays land on it, 90% of them within half the diagonal of
//! their centre), against the second tracer; and every path the second tracer finds over 5% is
//! reported.
inline Agreement compare(const Lens& lens, double angleX, double angleY) {
    GhostQuery q;
    q.angleXDeg = angleX, q.angleYDeg = angleY;
    auto report = analyseGhosts(lens, q);
    EXPECT_TRUE(report.ok()) << lens.name;
    Agreement a;
    if (!report.ok()) return a;
    const double diag = diagonal(lens);
    std::vector<GhostFigure> figures = report->ghosts;
    figures.push_back(report->direct);
    for (const GhostFigure& g : figures) {
        const reference::Figure r =
            reference::measure(lens, angleX, angleY, g.first, g.second, 128, 16384, 0.008);
        if (r.share > 0.05 && g.beamShare < 0.5 * r.share) {
            ++a.missing;
            ADD_FAILURE() << lens.name << " " << angleX << "," << angleY << " ghost " << g.first
                          << "," << g.second << ": share " << g.beamShare << ", reference "
                          << r.share;
        }
        if (r.share < 0.01 || r.landed < 0.5 || r.radius90 > diag / 2) continue;
        const double d = std::hypot(g.centerX - r.centerX, g.centerY - r.centerY) / diag;
        a.worst = std::max(a.worst, d);
        a.worstShare = std::max(a.worstShare, std::fabs(g.beamShare - r.share));
        ++a.compared;
        EXPECT_LT(d, 0.003) << lens.name << " " << angleX << "," << angleY << " ghost " << g.first
                            << "," << g.second << " (share " << r.share << ", on sensor "
                            << r.landed << ")";
        // Shares: the reference's own beam against flarekit's, both jittered.
        EXPECT_NEAR(g.beamShare, r.share, 0.002 + 0.02 * r.share)
            << lens.name << " ghost " << g.first << "," << g.second;
    }
    return a;
}

}  // namespace lensghosts
