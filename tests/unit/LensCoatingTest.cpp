// SPDX-License-Identifier: Apache-2.0
// Lens coatings against independent references: the quarter-wave closed forms, a single-layer
// characteristic matrix and Rouard's recursion for stacks, and the colours the shipped lenses'
// coatings give their ghosts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "flarekit/Lens.h"

using namespace flarekit;

namespace {

//! Single-layer reflectance by the characteristic (transfer) matrix method (Macleod, Thin-Film
//! Optical Filters, 2001, chapter 2), written out for one layer here; flarekit multiplies the
//! matrices of any stack (Rouard's recursion below is the independent check of stacks).
double matrixReflectance(double n0, double n1, double d, double n2, double cos0, double lambda) {
    using C = std::complex<double>;
    const double sin0 = std::sqrt(1 - cos0 * cos0);
    const C c1 = std::sqrt(C(1 - std::pow(n0 * sin0 / n1, 2))),
            c2 = std::sqrt(C(1 - std::pow(n0 * sin0 / n2, 2)));
    double r = 0;
    for (int pol = 0; pol < 2; ++pol) {
        // Tilted admittances: n cos for s, n / cos for p.
        const C y0 = pol == 0 ? C(n0 * cos0) : C(n0 / cos0);
        const C y1 = pol == 0 ? n1 * c1 : n1 / c1, y2 = pol == 0 ? n2 * c2 : n2 / c2;
        const C delta = 2 * M_PI * n1 * d * c1 / lambda;
        const C b = std::cos(delta) + C(0, 1) * std::sin(delta) / y1 * y2;
        const C c = C(0, 1) * y1 * std::sin(delta) + std::cos(delta) * y2;
        const C amp = (y0 * b - c) / (y0 * b + c);
        r += 0.5 * std::norm(amp);
    }
    return r;
}

}  // namespace

TEST(Lens, CoatingMatchesTheQuarterWaveClosedFormAndTheMatrixMethod) {
    const LensCoating mgf2 = mgf2Coating();
    for (const double n2 : {1.5168, 1.62, 1.7552, 1.9044}) {
        // At the design wavelength and normal incidence: ((n0 n2 - n1^2) / (n0 n2 + n1^2))^2.
        const double closed = std::pow((n2 - 1.38 * 1.38) / (n2 + 1.38 * 1.38), 2);
        EXPECT_NEAR(interfaceReflectance(1.0, n2, 1.0, mgf2, 550.0), closed, 1e-12) << n2;
        EXPECT_NEAR(interfaceReflectance(n2, 1.0, 1.0, mgf2, 550.0), closed, 1e-12) << n2;
        // Bare glass: Fresnel's ((n1 - n2) / (n1 + n2))^2.
        EXPECT_NEAR(interfaceReflectance(1.0, n2, 1.0, {}, 550.0), std::pow((n2 - 1) / (n2 + 1), 2),
                    1e-12);
        for (const double deg : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0}) {
            for (const double lambda : {450.0, 550.0, 650.0}) {
                const double c = std::cos(deg * M_PI / 180);
                EXPECT_NEAR(interfaceReflectance(1.0, n2, c, mgf2, lambda),
                            matrixReflectance(1.0, 1.38, mgf2.layers[0].thicknessNm, n2, c, lambda),
                            1e-9)
                    << n2 << " " << deg << " " << lambda;
            }
        }
    }
    // Past the critical angle from glass into air everything reflects.
    EXPECT_EQ(interfaceReflectance(1.6, 1.0, std::cos(50 * M_PI / 180), mgf2, 550), 1.0);
}

namespace {

//! Reflectance of a stack (layers from the n0 side) by Rouard's recursion: the amplitude of the
//! innermost interface, then each layer outward r = (r_j + r' e^{-2i d}) / (1 + r_j r' e^{-2i
//! d}): a second method, independent of the characteristic matrix flarekit uses.
double rouardReflectance(double n0, const std::vector<CoatingLayer>& layers, double n2, double cos0,
                         double lambda) {
    using C = std::complex<double>;
    const double inv = n0 * std::sqrt(1 - cos0 * cos0);  // n sin, the same in every medium
    const auto cosIn = [&](double n) { return std::sqrt(C(1 - (inv / n) * (inv / n))); };
    double r = 0;
    for (int pol = 0; pol < 2; ++pol) {
        const auto amp = [&](double na, double nb) {
            const C ca = cosIn(na), cb = cosIn(nb);
            return pol == 0 ? (na * ca - nb * cb) / (na * ca + nb * cb)
                            : (nb * ca - na * cb) / (nb * ca + na * cb);
        };
        C total = 0;
        for (std::size_t k = layers.size(); k-- > 0;) {
            const CoatingLayer& l = layers[k];
            const C rj = k + 1 == layers.size() ? amp(l.n, n2) : total;
            const C phase =
                std::exp(C(0, -2) * (2 * M_PI * l.n * l.thicknessNm / lambda) * cosIn(l.n));
            const double above = k == 0 ? n0 : layers[k - 1].n;
            const C ra = amp(above, l.n);
            total = (ra + rj * phase) / (1.0 + ra * rj * phase);
        }
        r += 0.5 * std::norm(total);
    }
    return r;
}

}  // namespace

// Multi-layer stacks against closed forms at the design wavelength and normal incidence (two
// quarter waves: R = ((n0 - Y) / (n0 + Y))^2, Y = n1^2 n_s / n2^2; a half-wave layer is absent
// there), and against Rouard's recursion at every angle and wavelength; the same from either
// side, as a lossless stack must be.
TEST(Lens, MultiLayerCoatingsMatchClosedFormsAndRouardsRecursion) {
    const double design = 530;
    const LensCoating qq{{quarterWave(1.38, design), quarterWave(1.70, design)}};
    const LensCoating broadband = coatingDesign(CoatingDesign::Broadband, design);
    ASSERT_EQ(broadband.layers.size(), 3u);
    for (const double ns : {1.5168, 1.62, 1.7552}) {
        const double y = 1.38 * 1.38 * ns / (1.70 * 1.70);
        EXPECT_NEAR(interfaceReflectance(1.0, ns, 1.0, qq, design), std::pow((1 - y) / (1 + y), 2),
                    1e-12)
            << ns;
        const double yb = 1.38 * 1.38 * ns / (kCeF3Index * kCeF3Index);
        EXPECT_NEAR(interfaceReflectance(1.0, ns, 1.0, broadband, design),
                    std::pow((1 - yb) / (1 + yb), 2), 1e-12)
            << ns;
        for (const LensCoating* c : {&qq, &broadband}) {
            for (const double deg : {0.0, 20.0, 40.0, 60.0, 80.0}) {
                const double cosAir = std::cos(deg * M_PI / 180);
                for (const double lambda : {420.0, 465.0, 550.0, 610.0, 690.0}) {
                    const double r = interfaceReflectance(1.0, ns, cosAir, *c, lambda);
                    EXPECT_NEAR(r, rouardReflectance(1.0, c->layers, ns, cosAir, lambda), 1e-10)
                        << ns << " " << deg << " " << lambda;
                    // The same ray from the glass side (the layers then met in reverse).
                    const double sinGlass = std::sin(deg * M_PI / 180) / ns;
                    EXPECT_NEAR(interfaceReflectance(ns, 1.0, std::sqrt(1 - sinGlass * sinGlass),
                                                     *c, lambda),
                                r, 1e-10)
                        << ns << " " << deg << " " << lambda;
                }
            }
        }
    }
    // A broadband stack reflects far less than bare glass across the visible, and its residual
    // peaks near the design wavelength between two minima (the colour of its ghosts).
    double peakAt = 0, peak = 0;
    for (double lambda = 440; lambda <= 640; lambda += 5) {
        const double r = interfaceReflectance(1.0, 1.62, 1.0, broadband, lambda);
        EXPECT_LT(r, 0.012) << lambda;
        if (r > peak) peak = r, peakAt = lambda;
    }
    EXPECT_NEAR(peakAt, design, 20.0);
}

// The shipped lenses state their coatings and their ghosts show it: the uncoated Petzval's are
// neutral, the single-coated double Gauss's magenta or purple (green weakest), the multi-coated
// zoom's include greens (green strongest); stripped of its coating the double Gauss's brightest
// ghosts are several times brighter in all.
TEST(Lens, ShippedCoatingsGiveTheirGhostsTheirColours) {
    const auto ghostsOf = [](const char* name, bool strip = false) {
        auto lens = loadLens(name);
        EXPECT_TRUE(lens.ok()) << name;
        if (strip && lens.ok())
            for (LensSurface& s : lens->surfaces) s.coating = {};
        GhostQuery q;
        q.angleXDeg = 8.0, q.gridSide = 24;
        q.ghostRays = 0;  // colours only
        auto r = analyseGhosts(*lens, q);
        EXPECT_TRUE(r.ok()) << name;
        return r.ok() ? r->ghosts : std::vector<GhostFigure>{};
    };
    const auto share = [](const GhostFigure& g, int c) {
        return g.intensity[std::size_t(c)] / (g.intensity[0] + g.intensity[1] + g.intensity[2]);
    };
    const auto petzval = ghostsOf("kodak-petzval");
    ASSERT_FALSE(petzval.empty());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(share(petzval[0], c), 1.0 / 3.0, 0.03) << c;
    const auto gauss = ghostsOf("angenieux-double-gauss");
    ASSERT_GE(gauss.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_LT(share(gauss[i], 1), share(gauss[i], 0)) << i;
        EXPECT_LT(share(gauss[i], 1), share(gauss[i], 2)) << i;
    }
    const auto zoom = ghostsOf("nikon-zoom-80-200");
    int green = 0;
    for (std::size_t i = 0; i < std::min<std::size_t>(zoom.size(), 8); ++i)
        green += share(zoom[i], 1) > std::max(share(zoom[i], 0), share(zoom[i], 2));
    EXPECT_GE(green, 2);
    const auto bare = ghostsOf("angenieux-double-gauss", true);
    ASSERT_FALSE(bare.empty());
    const auto total = [](const std::vector<GhostFigure>& ghosts) {
        double sum = 0;
        for (const GhostFigure& g : ghosts) sum += g.intensity[1];
        return sum;
    };
    EXPECT_GT(total(bare), 3.0 * total(gauss));
}
