// SPDX-License-Identifier: Apache-2.0
// The slow half of the ghost accuracy checks (ctest label `slow`): every shipped lens at 1, 6 and
// 12 degrees against the second tracer, and the centres' convergence at the default rays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "LensGhostCompare.h"

using namespace flarekit;
using namespace lensghosts;

TEST(LensGhostSweep, EveryShippedLensAt1To12Degrees) {
    for (const std::string& name : lensNames()) {
        const Lens lens = shipped(name);
        for (const double angle : {1.0, 6.0, 12.0}) {
            const Agreement a = compare(lens, angle, -angle / 2);
            std::printf(
                "independent tracer %-24s %4.1f deg: %3d ghosts, largest centre "
                "difference %.5f of the diagonal\n",
                name.c_str(), angle, a.compared, a.worst);
        }
    }
}

TEST(LensGhostSweep, CentresConvergeAtTheDefaultRays) {
    // A grazing ghost of the Takumar (rays near total internal reflection, a third of them off
    // the sensor) and compact ones: each centre moves by under 0.1% of the diagonal between the
    // default and four times the rays.
    const Lens lens = shipped("asahi-takumar-50");
    GhostQuery q;
    q.angleXDeg = 6, q.angleYDeg = -3;
    auto base = analyseGhosts(lens, q);
    q.ghostRays = 4 * kDefaultGhostRays;
    auto fine = analyseGhosts(lens, q);
    ASSERT_TRUE(base.ok() && fine.ok());
    std::map<std::pair<int, int>, GhostFigure> byPath;
    for (const GhostFigure& g : fine->ghosts) byPath[{g.first, g.second}] = g;
    int checked = 0, grazing = 0;
    for (const GhostFigure& g : base->ghosts) {
        if (g.beamShare < 0.01) continue;
        const GhostFigure& f = byPath[{g.first, g.second}];
        EXPECT_LT(std::hypot(g.centerX - f.centerX, g.centerY - f.centerY) / diagonal(lens), 0.001)
            << g.first << "," << g.second;
        if (g.onSensor < 0.7) ++grazing;
        ++checked;
    }
    EXPECT_GE(checked, 20);
    EXPECT_GE(grazing, 3);
}
