// SPDX-License-Identifier: Apache-2.0
// The slow half of the ghost accuracy checks (ctest label `slow`): every shipped lens, and lenses
// no one designed, at 1, 6 and 12 degrees against the second tracer, every lens at 1-20 degrees
// against the paraxial trace, and the centres' convergence at the default rays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "LensGhostCompare.h"
#include "LensParaxialReference.h"
#include "core/Random.h"

using namespace flarekit;
using namespace lensghosts;

TEST(LensGhostSweep, EveryShippedLensAt1To12Degrees) {
    for (const std::string& name : lensNames()) {
        const Lens lens = shippedLens(name);
        for (const double angle : {1.0, 6.0, 12.0}) {
            const Agreement a = compare(lens, angle, -angle / 2);
            std::printf(
                "independent tracer %-24s %4.1f deg: %3d ghosts, largest centre "
                "difference %.5f of the diagonal\n",
                name.c_str(), angle, a.compared, a.worst);
        }
    }
}

//! A lens no one designed: three to five spherical surfaces of random radius (either sign, 12 to
//! 80 mm), spacing, glass (n 1.45-1.9) and clear aperture (35-90% of the radius), the stop at a
//! random place, 30-70 mm to the sensor. Returns an empty lens when the surfaces cross.
Lens randomLens(SplitMix64& random) {
    const auto in = [&](double lo, double hi) { return lo + (hi - lo) * random.nextDouble(); };
    const int count = 3 + int(random.nextDouble() * 3);
    const int stopAt = int(random.nextDouble() * (count + 1));
    std::string text = R"({"sensor": {"width": 36, "height": 24}, "surfaces": [)";
    bool glass = false;
    for (int k = 0; k <= count; ++k) {
        if (k == stopAt)
            text += R"({"stop": true, "thickness": )" + std::to_string(in(0.5, 3)) +
                    R"(, "semi_aperture": )" + std::to_string(in(4, 12)) + "},";
        if (k == count) break;
        const double radius = (random.nextDouble() < 0.5 ? -1 : 1) * in(12, 80);
        glass = k + 1 < count && !glass;  // glass and air alternate; air behind the last
        text += R"({"radius": )" + std::to_string(radius) + R"(, "thickness": )" +
                std::to_string(k + 1 < count ? in(1, 8) : in(30, 70)) + R"(, "n_d": )" +
                std::to_string(glass ? in(1.45, 1.9) : 1.0) + R"(, "semi_aperture": )" +
                std::to_string(std::fabs(radius) * in(0.35, 0.9)) + "}" +
                (k + 1 < count ? "," : "");
    }
    text += "]}";
    auto lens = parseLens(text, "random.json");
    return lens.ok() ? *lens : Lens{};
}

TEST(LensGhostSweep, LensesNoOneDesignedAt1To12Degrees) {
    SplitMix64 random(2026);
    int lenses = 0, compared = 0;
    while (lenses < 16) {
        const Lens lens = randomLens(random);
        GhostQuery widest;
        widest.angleXDeg = 12, widest.angleYDeg = -6;
        if (lens.surfaces.empty() || !analyseGhosts(lens, widest).ok()) continue;
        ++lenses;
        for (const double angle : {1.0, 6.0, 12.0}) {
            const Agreement a = compare(lens, angle, -angle / 2);
            compared += a.compared;
            std::printf(
                "independent tracer, random lens %d (%zu surfaces) %4.1f deg: %3d ghosts, "
                "largest centre difference %.5f of the diagonal\n",
                lenses, lens.surfaces.size(), angle, a.compared, a.worst);
        }
    }
    EXPECT_GE(compared, 80);
}

TEST(LensGhostSweep, ParaxialTableAt1To20Degrees) {
    // docs/lens.md's table: every lens at 1, 5, 10 and 20 degrees against the paraxial trace
    // (printed; at 1 degree the same bound as the unit test).
    EXPECT_GE(paraxialref::compareWithParaxial({1.0, 5.0, 10.0, 20.0}), 80);
}

TEST(LensGhostSweep, CentresConvergeAtTheDefaultRays) {
    // A grazing ghost of the Takumar (rays near total internal reflection, a third of them off
    // the sensor) and compact ones: each centre moves by under 0.1% of the diagonal between the
    // default and four times the rays.
    const Lens lens = shippedLens("asahi-takumar-50");
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
