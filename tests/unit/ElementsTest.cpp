// SPDX-License-Identifier: Apache-2.0
// Elements tested as maths: support, symmetry, energy against the analytic integral,
// determinism. Integrals are computed here from the definitions, not from flarekit code.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "elements/ElementKernel.h"
#include "flarekit/Elements.h"
#include "flarekit/Flare.h"

using namespace flarekit;

namespace {

constexpr double kPi = std::numbers::pi;

double energy(const Image& img, int channel = 0) {
    double sum = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) sum += (&img.at(x, y).r)[channel];
    }
    return sum;
}

// Largest value found at distance >= minDistance from the image centre.
float maxBeyond(const Image& img, double minDistance) {
    float m = 0.f;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const double dx = x + 0.5 - img.width() / 2.0, dy = y + 0.5 - img.height() / 2.0;
            if (std::hypot(dx, dy) >= minDistance)
                m = std::max({m, img.at(x, y).r, img.at(x, y).a});
        }
    }
    return m;
}

ElementParams plain(ElementType type) {
    ElementParams p = defaultElement(type);
    p.color = {1.f, 1.f, 1.f};
    p.innerColor.reset();
    p.intensity = 1.f;
    p.softness = 0.f;
    return p;
}

}  // namespace

TEST(Elements, EveryTypeIsZeroPastItsRadius) {
    for (int t = 0; t < kElementTypeCount; ++t) {
        ElementParams p = defaultElement(ElementType(t));
        p.aspect = 1.f;  // the bound renderElement states is for unstretched elements
        if (p.type == ElementType::Image) {
            // A round texture (an image's square corners reach past the radius by design).
            Image disc(32, 32);
            for (int y = 0; y < 32; ++y)
                for (int x = 0; x < 32; ++x)
                    if (std::hypot(x + 0.5 - 16, y + 0.5 - 16) < 12) disc.at(x, y) = {1, 1, 1, 1};
            p.textureImage = std::make_shared<const Image>(std::move(disc));
        }
        for (float radius : {7.3f, 40.f, 123.5f}) {
            const Image img = renderElement(p, radius);
            EXPECT_EQ(maxBeyond(img, radius + 1.0), 0.f)
                << elementTypeName(p.type) << " R=" << radius;
            EXPECT_GT(energy(img), 0.0) << elementTypeName(p.type);
        }
    }
}

TEST(Elements, RoundElementsAreRotationallySymmetric) {
    for (ElementType type : {ElementType::Glow, ElementType::Ring, ElementType::Disc}) {
        const Image img = renderElement(defaultElement(type), 50.f);
        const int n = img.width();
        ASSERT_EQ(img.width(), img.height());
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const float v = img.at(x, y).r;
                ASSERT_NEAR(v, img.at(n - 1 - x, y).r, 1e-5f);  // mirror
                ASSERT_NEAR(v, img.at(y, x).r, 1e-5f);          // transpose
                ASSERT_NEAR(v, img.at(n - 1 - y, x).r, 1e-5f);  // quarter turn
            }
        }
    }
}

TEST(Elements, StreaksAndPolygonsHaveTheirSymmetry) {
    ElementParams streaks = plain(ElementType::Streaks);
    streaks.count = 4;
    const Image s = renderElement(streaks, 60.f);
    ElementParams hexagon = plain(ElementType::Polygon);
    hexagon.blades = 6;
    const Image h = renderElement(hexagon, 60.f);
    const int n = s.width();
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            ASSERT_NEAR(s.at(x, y).r, s.at(n - 1 - y, x).r,
                        1e-4f);  // 4 streaks: quarter-turn symmetric
            ASSERT_NEAR(h.at(x, y).r, h.at(x, h.height() - 1 - y).r,
                        1e-5f);  // hexagon: mirror about x axis
            ASSERT_NEAR(h.at(x, y).r, h.at(h.width() - 1 - x, y).r, 1e-5f);  // and about y axis
        }
    }
}

TEST(Elements, GlowEnergyMatchesTheSeedFalloffIntegral) {
    // g(d) = (f(128 d) - f(128)) / (1 - f(128)), f(i) = exp(-0.006 i^2)/2 + exp(-0.03 i)/2 (Tanczos
    // 1999).
    auto f = [](double i) { return std::exp(-i * i * 0.006) * 0.5 + std::exp(-i * 0.03) * 0.5; };
    double integral = 0;  // 2*pi * int_0^1 g(d) d dd, midpoint rule
    const int steps = 200000;
    for (int k = 0; k < steps; ++k) {
        const double d = (k + 0.5) / steps;
        integral += (f(128 * d) - f(128)) / (1 - f(128)) * d / steps;
    }
    integral *= 2 * kPi;
    const float radius = 150.f;
    const double measured =
        energy(renderElement(plain(ElementType::Glow), radius)) / (radius * radius);
    EXPECT_NEAR(measured / integral, 1.0, 0.01);
}

TEST(Elements, RingDiscAndPolygonEnergyMatchTheirAreas) {
    const float radius = 200.f;
    ElementParams ring = plain(ElementType::Ring);
    ring.width = 0.1f;
    const double ringArea = kPi * (1.0 - 0.9 * 0.9);
    EXPECT_NEAR(energy(renderElement(ring, radius)) / (radius * radius) / ringArea, 1.0, 0.005);

    EXPECT_NEAR(energy(renderElement(plain(ElementType::Disc), radius)) / (radius * radius) / kPi,
                1.0, 0.003);

    for (int blades : {3, 5, 6, 8}) {
        ElementParams poly = plain(ElementType::Polygon);
        poly.blades = blades;
        const double area = blades / 2.0 * std::sin(2 * kPi / blades);  // circumradius 1
        EXPECT_NEAR(energy(renderElement(poly, radius)) / (radius * radius) / area, 1.0, 0.005)
            << blades;
    }
}

TEST(Elements, StreakEnergyIsCountTimesWidthTimesFalloffIntegral) {
    // Each streak: a strip of width `thickness`, length 1, brightness (1 - r)^p -> thickness / (p +
    // 1).
    for (int count : {2, 4, 6}) {
        for (float falloff : {1.f, 2.5f}) {
            ElementParams p = plain(ElementType::Streaks);
            p.count = count;
            p.thickness = 0.02f;
            p.falloff = falloff;
            const float radius = 300.f;
            const double analytic = count * 0.02 / (falloff + 1.0);
            EXPECT_NEAR(energy(renderElement(p, radius)) / (radius * radius) / analytic, 1.0, 0.02)
                << count << " streaks, falloff " << falloff;
        }
    }
}

TEST(Elements, SoftnessBlursWithoutChangingMuchEnergy) {
    ElementParams hard = plain(ElementType::Disc), soft = hard;
    soft.softness = 0.3f;
    const Image a = renderElement(hard, 100.f), b = renderElement(soft, 100.f);
    // The blur is kept inside the rim, so the soft disc is smaller: edge at 1 - 0.15.
    EXPECT_NEAR(energy(b) / energy(a), 0.85 * 0.85 + 0.3 * 0.3 / 12.0, 0.01);
    // Ramp 0.3 wide centred on the edge 1 - (0.3 - 1/R)/2 = 0.855, so it ends at the rim plus
    // half a pixel; pixel x has its centre at d = (x + 0.5) / R.
    EXPECT_NEAR(b.at(b.width() / 2 + 99, b.height() / 2).r, (0.855f - 0.995f) / 0.3f + 0.5f, 1e-4f);
    EXPECT_NEAR(b.at(b.width() / 2 + 85, b.height() / 2).r, 0.5f, 1e-4f);
    EXPECT_FLOAT_EQ(b.at(b.width() / 2 + 60, b.height() / 2).r, 1.f);
    EXPECT_GT(a.at(a.width() / 2 + 98, a.height() / 2).r, 0.99f);
}

TEST(Elements, AspectStretchesTheShapeAndScalesTheEnergy) {
    ElementParams p = plain(ElementType::Disc), wide = p;
    wide.aspect = 2.5f;
    const Image a = renderElement(p, 80.f), b = renderElement(wide, 80.f);
    EXPECT_GT(b.width(), 2 * a.width());
    EXPECT_EQ(b.height(), a.height());
    EXPECT_NEAR(energy(b) / energy(a), 2.5, 0.01);
}

TEST(Elements, SameParamsSameImageAndSeedsDiffer) {
    ElementParams rays = defaultElement(ElementType::Rays);
    rays.seed = 1234;
    const Image a = renderElement(rays, 64.f), b = renderElement(rays, 64.f);
    ASSERT_EQ(a.pixelCount(), b.pixelCount());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.pixelCount() * sizeof(Rgba)));
    rays.seed = 1235;
    const Image c = renderElement(rays, 64.f);
    EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.pixelCount() * sizeof(Rgba)));
}

TEST(Elements, RaysHaveRandomLengthsWithinRange) {
    ElementParams rays = plain(ElementType::Rays);
    rays.count = 40;
    rays.thickness = 0.01f;
    rays.minLength = 0.3f;
    rays.falloff = 0.f;  // constant brightness so the tip is where the ray ends
    const std::vector<Spike> spikes = makeSpikes(rays);
    ASSERT_EQ(spikes.size(), 40u);
    float shortest = 1.f, longest = 0.f;
    for (const Spike& s : spikes) {
        EXPECT_GE(s.length, 0.3f);
        EXPECT_LE(s.length, 1.f);
        shortest = std::min(shortest, s.length);
        longest = std::max(longest, s.length);
    }
    EXPECT_GT(longest - shortest, 0.3f);  // random, not all equal
    // Rendered, each ray is lit along its own angle up to its length and dark past it.
    const float radius = 200.f;
    const Image img = renderElement(rays, radius);
    const double cx = img.width() / 2.0, cy = img.height() / 2.0;
    for (const Spike& s : spikes) {
        auto at = [&](double r) {
            return img.at(int(cx + r * std::cos(s.angle)), int(cy + r * std::sin(s.angle))).r;
        };
        EXPECT_GT(at((s.length - 0.03) * radius), 0.f) << s.angle;
        EXPECT_GT(at(0.5 * s.length * radius), 0.f) << s.angle;
    }
}

TEST(Elements, GradientRunsFromInnerToOuterColour) {
    ElementParams p = plain(ElementType::Disc);
    p.color = {1.f, 0.f, 0.f};
    p.innerColor = Rgb{0.f, 0.f, 1.f};
    const Image img = renderElement(p, 100.f);
    const Rgba centre = img.at(img.width() / 2, img.height() / 2);
    const Rgba nearRim = img.at(img.width() / 2 + 97, img.height() / 2);
    EXPECT_GT(centre.b, 0.98f);
    EXPECT_LT(centre.r, 0.02f);
    EXPECT_GT(nearRim.r, 0.95f);
    EXPECT_LT(nearRim.b, 0.05f);
}

// Across a streak the brightness rises and falls smoothly at any resolution: between
// neighbouring pixels it never steps by more than a quarter of the profile's peak. Checked on
// every streak and ray element of every shipped preset, laid horizontal, at 1080p and 4K, with
// the spike's centre on a pixel centre (the worst case) and between two pixel centres.
TEST(Elements, StreakProfileIsSmoothAcrossItsWidthAtAnyResolution) {
    std::size_t checked = 0;
    for (const std::string& name : shippedPresetNames()) {
        const Result<Preset> preset = loadPreset(name);
        ASSERT_TRUE(preset.ok()) << name;
        for (ElementParams e : preset->elements) {
            if (e.type != ElementType::Streaks && e.type != ElementType::Rays) continue;
            e.type = ElementType::Streaks;  // one spike along +x: the profile is a column
            e.count = 1;
            e.rotationDeg = 0.f;
            for (int height : {1080, 2160}) {
                const float radius = e.size * float(height);
                const ElementKernel k = prepareElement(e, radius);
                for (float centre : {0.f, 0.5f}) {
                    float peak = 0.f, step = 0.f, previous = 0.f;
                    for (int j = -200; j <= 200; ++j) {
                        const float v =
                            shadeElement(k, 0.3f * radius * e.aspect, float(j) + centre).r;
                        peak = std::max(peak, v);
                        if (j > -200) step = std::max(step, std::abs(v - previous));
                        previous = v;
                    }
                    ASSERT_GT(peak, 0.f) << name;
                    EXPECT_LE(step, 0.25f * peak)
                        << name << " thickness " << e.thickness << " at " << height << "p";
                    ++checked;
                }
            }
        }
    }
    EXPECT_GE(checked, 8u);  // anamorphic, hexagon-ghosts, starburst, sun-wide, tanczos-classic
}

// A wide streak is a Gaussian core, not a box: it has no flat top and no hard edge.
TEST(Elements, WideStreakHasAGaussianCoreNotAFlatBar) {
    ElementParams p = plain(ElementType::Streaks);
    p.count = 1;
    p.thickness = 0.05f;  // 15 px full width at half maximum at radius 300
    p.falloff = 0.f;
    const ElementKernel k = prepareElement(p, 300.f);
    const float peak = shadeElement(k, 150.f, 0.f).r;
    // Half maximum of the core at half the thickness (the wing adds its own small share).
    const float half = shadeElement(k, 150.f, 7.5f).r;
    EXPECT_NEAR(half / peak, 0.85f * 0.5f + 0.15f * std::exp(-7.5f / 15.f), 0.01f);
    EXPECT_LT(shadeElement(k, 150.f, 3.f).r, 0.95f * peak);  // no flat top
    EXPECT_GT(shadeElement(k, 150.f, 15.f).r, 0.f);          // a soft tail past the width
}

// Spikes are shaded the same whichever way a pixel finds the ones that reach it (a few streaks
// are each tested, many rays searched by angle): against a sum over every spike written here
// from the definitions, on a grid across the element, zero exactly where it is zero.
TEST(Elements, SpikesSumEverySpikeThatReachesThePixel) {
    for (const auto& [type, count] :
         {std::pair{ElementType::Streaks, 4}, std::pair{ElementType::Streaks, 12},
          std::pair{ElementType::Streaks, 13}, std::pair{ElementType::Rays, 40}}) {
        ElementParams p = plain(type);
        p.count = count;
        p.thickness = 0.02f;
        p.falloff = 1.5f;
        const ElementKernel k = prepareElement(p, 200.f);
        int lit = 0;
        for (int j = -60; j <= 60; ++j) {
            for (int i = -60; i <= 60; ++i) {
                const float x = float(i) / 55.f, y = float(j) / 55.f + 0.003f;
                double sum = 0;
                for (const Spike& s : k.spikes) {
                    const float along = x * std::cos(s.angle) + y * std::sin(s.angle);
                    const float perp = y * std::cos(s.angle) - x * std::sin(s.angle);
                    if (along <= 0.f || along >= s.length || std::abs(perp) >= k.maxHalfWidth)
                        continue;
                    sum += double(s.weight) * spikeAcross(k.spikeProfile, perp) *
                           std::pow(1.0 - double(along) / double(s.length), double(p.falloff));
                }
                const float shaded = shadeSpikes(k, x, y).a;
                if (sum == 0) {
                    ASSERT_EQ(shaded, 0.f) << count << " at " << x << "," << y;
                } else {
                    ++lit;
                    ASSERT_NEAR(shaded, std::min(sum, 1.0), 1e-4 * std::min(sum, 1.0) + 1e-6)
                        << count << " at " << x << "," << y;
                }
            }
        }
        EXPECT_GT(lit, 200) << count;
    }
}
