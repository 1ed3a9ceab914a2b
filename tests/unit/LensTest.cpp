// SPDX-License-Identifier: Apache-2.0
// Lens prescriptions and their optics, each against an independent reference: the patents'
// stated focal lengths, the Fresnel closed form, a paraxial y-nu trace of every ghost path,
// energy bounds. Coatings: LensCoatingTest.cpp; the starburst: LensStarburstTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>
#include "LensParaxialReference.h"

#include "ShippedLens.h"
#include "flarekit/Lens.h"
#include "lens/LensTrace.h"

using namespace flarekit;

namespace {

using test::shippedLens;

std::string lensError(const std::string& text) {
    auto lens = parseLens(text, "lens.json");
    return lens.ok() ? std::string("(accepted)") : lens.error().message;
}

const char* kSimple = R"({"surfaces": [
  {"radius": 50, "thickness": 5, "n_d": 1.5168, "v_d": 64.17, "semi_aperture": 10},
  {"radius": -50, "thickness": 5, "semi_aperture": 10},
  {"stop": true, "thickness": 40, "semi_aperture": 5}]})";

}  // namespace

TEST(Lens, ShippedPrescriptionsMatchTheirPatentsFocalLengths) {
    const auto names = lensNames();
    ASSERT_GE(names.size(), 5u);
    std::size_t longest = 0;
    for (const std::string& name : names) {
        const Lens lens = shippedLens(name);
        longest = std::max(longest, lens.surfaces.size());
        const double f = paraxial(lens).focalLength;
        if (lens.patentFocalLength > 0) {
            EXPECT_NEAR(f, lens.patentFocalLength, 0.01 * lens.patentFocalLength) << name;
        }
    }
    EXPECT_GE(longest, 15u) << "a zoom of 15+ surfaces";
    // The zoom's table is scaled (see its source): its two ends must keep the patent's 80-200
    // ratio, which checks every variable gap and group power of the transcription.
    const double ratio = paraxial(shippedLens("nikon-zoom-80-200-tele")).focalLength /
                         paraxial(shippedLens("nikon-zoom-80-200")).focalLength;
    EXPECT_NEAR(ratio, 200.0 / 80.0, 0.01 * 2.5);
}

TEST(Lens, ATelephotoIsShorterThanItsFocalLength) {
    // A telephoto design puts its image closer to the front vertex than f (total track over f,
    // the telephoto ratio, below 1); the Canon zoom's long end is one (its patent's track 189.7 mm
    // at f = 205.3), its short end is not.
    const auto trackOverF = [](const Lens& lens) {
        double track = 0.0;
        for (const LensSurface& s : lens.surfaces) track += s.thickness;
        return track / paraxial(lens).focalLength;
    };
    EXPECT_NEAR(trackOverF(shippedLens("canon-zoom-70-210-tele")), 189.68 / 205.31, 0.005);
    EXPECT_GT(trackOverF(shippedLens("canon-zoom-70-210")), 2.0);
}

TEST(Lens, ThinLensFocalLengthIsTheLensmakersFormula) {
    // A thick biconvex lens: 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)).
    auto lens = parseLens(kSimple, "simple.json");
    ASSERT_TRUE(lens.ok()) << lens.error().message;
    const double n = 1.5168, r1 = 50, r2 = -50, d = 5;
    const double f = 1.0 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * d / (n * r1 * r2)));
    EXPECT_NEAR(paraxial(*lens).focalLength, f, 1e-9 * f);
}

TEST(Lens, BadPrescriptionsAreRefusedWithTheirField) {
    // Each prescription and (a part of) the one line it is refused with.
    const struct {
        const char* lens;
        const char* error;
    } cases[] = {
        {R"({"surfaces": [{"radius": 50, "thickness": 5, "n_d": 1.5, "semi_aperture": 10},
            {"stop": true, "thickness": 1, "semi_aperture": 5},
            {"radius": 0, "thickness": 1, "semi_aperture": 5},
            {"radius": 0, "thickness": 40, "semi_aperture": -2}]})",
         "lens.json: surfaces[3].semi_aperture: expected a positive number, got -2"},
        {R"({"surfaces": [{"radius": 50, "thickness": 5, "n_d": 0.9, "semi_aperture": 10},
            {"stop": true, "thickness": 40, "semi_aperture": 5}]})",
         "lens.json: surfaces[0].n_d: expected a number in [1, 3], got 0.9"},
        {R"({"surfaces": [{"radius": 50, "thickness": 5, "n_d": 1.5, "semi_aperture": 10},
            {"radius": -50, "thickness": 40, "semi_aperture": 10}]})",
         "lens.json: surfaces: expected exactly one surface with \"stop\": true, found 0"},
        {R"({"surfaces": [{"stop": true, "thickness": 5, "semi_aperture": 10},
            {"stop": true, "thickness": 40, "semi_aperture": 10}]})",
         "found 2"},
        // A biconvex element 1 mm thick with a 20 mm clear radius: its faces cross at the rim.
        {R"({"surfaces": [{"radius": 50, "thickness": 1, "n_d": 1.5, "semi_aperture": 20},
            {"radius": -50, "thickness": 5, "semi_aperture": 20},
            {"stop": true, "thickness": 40, "semi_aperture": 5}]})",
         "lens.json: surfaces[0].thickness: 1 makes surfaces 0 and 1 cross"},
        {R"({"surfaces": [{"radius": 10, "thickness": 5, "n_d": 1.5, "semi_aperture": 12},
            {"stop": true, "thickness": 40, "semi_aperture": 5}]})",
         "lens.json: surfaces[0].semi_aperture: 12 is not below |radius| 10"},
        {R"({"surfaces": [{"radius": 50, "thickness": 5, "semi_aperture": 10, "coating": "gold"},
            {"stop": true, "thickness": 40, "semi_aperture": 5}]})",
         "lens.json: surfaces[0].coating: expected \"none\", \"mgf2\""},
        {R"({"surfaces": [], "focus": 1})", "lens.json: focus: unknown key"},
    };
    for (const auto& c : cases) {
        const std::string error = lensError(c.lens);
        EXPECT_NE(error.find(c.error), std::string::npos) << error;
        EXPECT_EQ(error.rfind("lens.json: ", 0), 0u) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

TEST(Lens, DispersionHoldsTheDLineAndTheAbbeNumber) {
    LensSurface s;
    s.nd = 1.5168, s.vd = 64.17;
    EXPECT_NEAR(refractiveIndex(s, kLineD), 1.5168, 1e-12);
    EXPECT_NEAR((s.nd - 1) / (refractiveIndex(s, kLineF) - refractiveIndex(s, kLineC)), 64.17,
                1e-9);
    EXPECT_GT(refractiveIndex(s, 450), refractiveIndex(s, 650));  // normal dispersion
}

namespace {

//! A slow uncoated triplet-like lens whose rays stay near the axis, so every reflection is
//! close to normal incidence.
const char* kSlow = R"({"surfaces": [
  {"radius": 60, "thickness": 4, "n_d": 1.6, "v_d": 40, "semi_aperture": 4},
  {"radius": -200, "thickness": 6, "semi_aperture": 4},
  {"stop": true, "thickness": 6, "semi_aperture": 2},
  {"radius": -40, "thickness": 2, "n_d": 1.7, "v_d": 30, "semi_aperture": 4},
  {"radius": -80, "thickness": 80, "semi_aperture": 4}],
  "sensor": {"width": 200, "height": 150}})";

double normalReflectance(const Lens& lens, int i, double lambda) {
    const double before = i == 0 ? 1.0 : refractiveIndex(lens.surfaces[std::size_t(i) - 1], lambda);
    return interfaceReflectance(before, refractiveIndex(lens.surfaces[std::size_t(i)], lambda), 1.0,
                                lens.surfaces[std::size_t(i)].coating, lambda);
}

}  // namespace

TEST(Lens, GhostEnergyIsBoundedByItsReflectances) {
    auto lens = parseLens(kSlow, "slow.json");
    ASSERT_TRUE(lens.ok()) << lens.error().message;
    GhostQuery q;
    q.angleXDeg = 1.0;
    auto r = analyseGhosts(*lens, q);
    ASSERT_TRUE(r.ok()) << r.error().message;
    // 4 reflecting surfaces (the stop never reflects): 6 pairs.
    ASSERT_EQ(r->ghosts.size(), 6u);
    std::array<double, 3> sum = r->direct.intensity;
    for (const GhostFigure& g : r->ghosts) {
        EXPECT_NE(g.first, 2);
        EXPECT_NE(g.second, 2);
        for (int c = 0; c < 3; ++c) {
            const double lambda = kRgbWavelengthsNm[std::size_t(c)];
            // Near normal incidence the unpolarised reflectance is its normal value to 1e-3.
            const double bound = normalReflectance(*lens, g.first, lambda) *
                                 normalReflectance(*lens, g.second, lambda) * 1.001;
            EXPECT_LE(g.intensity[std::size_t(c)], bound) << g.first << "," << g.second;
            EXPECT_GT(g.intensity[std::size_t(c)], 0.0) << g.first << "," << g.second;
            sum[std::size_t(c)] += g.intensity[std::size_t(c)];
        }
    }
    for (double s : sum) EXPECT_LT(s, 1.0);
    // A ray that cannot reach the sensor carries nothing: at 60 degrees nothing passes the stop.
    q.angleXDeg = 60;
    EXPECT_FALSE(analyseGhosts(*lens, q).ok());
    for (const std::string& name : lensNames()) {
        GhostQuery q0;
        q0.ghostRays = 0;  // shares only
        auto all = analyseGhosts(shippedLens(name), q0);
        ASSERT_TRUE(all.ok()) << name;
        double total = all->direct.intensity[1];
        for (const GhostFigure& g : all->ghosts) {
            total += g.intensity[1];
            if (g.rays == 0) {
                EXPECT_EQ(g.intensity[1] + g.intensity[0] + g.intensity[2], 0.0) << name;
            }
        }
        EXPECT_LT(total, 1.0) << name;
    }
}

TEST(Lens, GhostCentresAgreeWithAParaxialTraceAtSmallAngles) {
    // Every lens at 1 degree (LensParaxialReference.h); the table at 1-20 degrees is
    // LensGhostSweep.ParaxialTableAt1To20Degrees (label slow).
    EXPECT_GE(paraxialref::compareWithParaxial({1.0}), 30);
}

TEST(Lens, RenderedGhostsCarryTheirReportedEnergy) {
    // One source, one ghost, no starburst or glare: the ghost layer's sum is the source's
    // energy times the ghost's share (the mesh's irradiance integrates back to its flux).
    auto lens = parseLens(kSlow, "slow.json");
    ASSERT_TRUE(lens.ok());
    LensRenderOptions o;
    o.ghosts = 1, o.starburst = 0, o.glare = 0, o.gridSide = 96;
    o.ghostLevel = GhostLevel::Physical;
    LensLight light;
    light.x = 160, light.y = 120;  // on the axis of a 320 x 240 frame: the ghost is whole in it
    // Bright enough that no triangle falls under the renderer's visibility floor.
    light.energy = {1e7, 1e7, 1e7};
    auto layers = renderLensFlare(*lens, 320, 240, {light}, o);
    ASSERT_TRUE(layers.ok()) << layers.error().message;
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const Rgba& p = layers->ghosts.at(x, y);
            sum[0] += p.r, sum[1] += p.g, sum[2] += p.b;
        }
    // The same ghost through the analysis, at the light's field angle.
    GhostQuery q;
    q.gridSide = 200;
    q.ghostRays = 0;  // shares only
    auto report = analyseGhosts(*lens, q);
    ASSERT_TRUE(report.ok());
    const GhostFigure& g = report->ghosts.front();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c], 1e7 * g.intensity[std::size_t(c)],
                    0.03 * 1e7 * g.intensity[std::size_t(c)])
            << c;
    // At the flux level the brightest ghost carries kFluxGhostShare of the light's energy
    // (luminance), its colour as traced: the physical figures times share / luminance(share).
    o.ghostLevel = GhostLevel::Flux;
    auto flux = renderLensFlare(*lens, 320, 240, {light}, o);
    ASSERT_TRUE(flux.ok());
    double fluxSum[3] = {0, 0, 0};
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const Rgba& p = flux->ghosts.at(x, y);
            fluxSum[0] += p.r, fluxSum[1] += p.g, fluxSum[2] += p.b;
        }
    EXPECT_NEAR(0.2126 * fluxSum[0] + 0.7152 * fluxSum[1] + 0.0722 * fluxSum[2],
                1e7 * kFluxGhostShare, 0.05 * 1e7 * kFluxGhostShare);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fluxSum[c] / fluxSum[1], sum[c] / sum[1], 1e-3) << c;
}

TEST(Lens, BakedPresetsPlaceEachGhostWhereTheTraceDoes) {
    const Lens lens = shippedLens("nikon-zoom-80-200");
    auto preset = bakeLens(lens, 12);
    ASSERT_TRUE(preset.ok()) << preset.error().message;
    // A glow and the 9-bladed iris's 18 spikes at the light, then the ghosts.
    ASSERT_GE(preset->elements.size(), 3u);
    EXPECT_EQ(preset->elements[0].type, ElementType::Glow);
    EXPECT_EQ(preset->elements[1].type, ElementType::Streaks);
    EXPECT_EQ(preset->elements[1].count, 18);
    // The same trace the bake makes: each ghost's t is its centre over the light's image.
    GhostQuery q;
    q.angleXDeg = std::atan(0.3 * lens.sensor.height / paraxial(lens).focalLength) * 180 / M_PI;
    q.ghostRays = 4096;  // as the bake traces
    auto report = analyseGhosts(lens, q);
    ASSERT_TRUE(report.ok());
    std::size_t matched = 0;
    for (std::size_t i = 2; i < preset->elements.size(); ++i) {
        const ElementParams& e = preset->elements[i];
        EXPECT_EQ(e.type, ElementType::Polygon);
        EXPECT_EQ(e.blades, 9);
        EXPECT_LE(e.intensity, 0.35f + 1e-6f);
        for (const GhostFigure& g : report->ghosts) {
            if (std::fabs(float(g.centerX / report->direct.centerX) - e.t) < 1e-6f &&
                std::fabs(float(g.radius90 / lens.sensor.height) - e.size) < 1e-6f) {
                ++matched;
                break;
            }
        }
    }
    EXPECT_EQ(matched, preset->elements.size() - 2);
    // Its JSON reads back to the same preset, and so does every shipped one's.
    auto back = parsePreset(presetToJson(*preset), "baked.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(presetToJson(*back), presetToJson(*preset));
    for (const std::string& name : shippedPresetNames()) {
        auto p = loadPreset(name);
        ASSERT_TRUE(p.ok());
        auto again = parsePreset(presetToJson(*p), name + ".json");
        ASSERT_TRUE(again.ok()) << name << ": " << again.error().message;
        ASSERT_EQ(again->elements.size(), p->elements.size());
        for (std::size_t i = 0; i < p->elements.size(); ++i) {
            EXPECT_EQ(again->elements[i].t, p->elements[i].t) << name;
            EXPECT_EQ(again->elements[i].size, p->elements[i].size) << name;
            EXPECT_EQ(again->elements[i].color, p->elements[i].color) << name;
            EXPECT_EQ(again->elements[i].innerColor, p->elements[i].innerColor) << name;
            EXPECT_EQ(again->elements[i].blend, p->elements[i].blend) << name;
            EXPECT_EQ(again->elements[i].seed, p->elements[i].seed) << name;
        }
    }
}

TEST(Lens, SmallMeshGridsAgreeWithTheExactTrace) {
    // The real-time path is the same traced mesh at a coarse grid (Hullin et al. 2011 use
    // 16-32 rays a side). Its ghost's energy and centroid against the exact analysis.
    auto lens = parseLens(kSlow, "slow.json");
    ASSERT_TRUE(lens.ok());
    LensLight light;
    // 8 px right of the axis: 5 mm on this sensor. The field angle whose direct image lands
    // there (this lens's sensor is not at its focus, so that is not the paraxial angle), found
    // as the renderer finds it, here through the analysis itself.
    light.x = 168, light.y = 120;
    light.energy = {1e7, 1e7, 1e7};
    const double mm = std::min(200.0 / 320, 150.0 / 240);
    GhostQuery q;
    q.gridSide = 200;
    double tanX = 8 * mm / paraxial(*lens).focalLength;
    Result<GhostReport> report = invalidInput("not traced");
    for (int iter = 0; iter < 4; ++iter) {
        q.angleXDeg = std::atan(tanX) * 180 / M_PI;
        report = analyseGhosts(*lens, q);
        ASSERT_TRUE(report.ok());
        tanX *= 8 * mm / report->direct.centerX;
    }
    const GhostFigure& g = report->ghosts.front();
    for (const int grid : {8, 16, 32, 96}) {
        LensRenderOptions o;
        o.ghosts = 1, o.starburst = 0, o.glare = 0, o.gridSide = grid;
        o.ghostLevel = GhostLevel::Physical;
        auto layers = renderLensFlare(*lens, 320, 240, {light}, o);
        ASSERT_TRUE(layers.ok());
        double sum = 0, cx = 0;
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x) {
                const double v = layers->ghosts.at(x, y).g;
                sum += v, cx += v * (x + 0.5);
            }
        const double energyError = sum / (1e7 * g.intensity[1]) - 1;
        // The exact figure is the mean of the rays reaching the sensor, the rendered one the
        // energy-weighted mean: near enough for a ghost of nearly even throughput.
        const double centreError = (cx / sum - 160) * mm - g.centerX;  // mm on the sensor
        std::printf("mesh grid %3d: ghost energy %+.2f%%, centroid %+.4f mm\n", grid,
                    100 * energyError, centreError);
        if (grid >= 16) {
            EXPECT_LT(std::fabs(energyError), 0.05) << grid;
            EXPECT_LT(std::fabs(centreError), 0.5 * mm) << grid;
        }
    }
}

TEST(Lens, IrisConvexityIsWhatTheRendererAssumes) {
    // The renderer skips the iris mask on triangles whose vertices are inside a convex iris;
    // check the convexity rule against the shape itself: along random chords q never exceeds
    // its ends' larger value where the rule says convex. (The rule is sufficient, not
    // necessary: a shape it calls non-convex is merely tested per pixel.)
    std::uint64_t state = 12345;
    const auto uniform = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1.0p-53 * 2 - 1;
    };
    int checked = 0;
    for (const int blades : {3, 4, 5, 6, 9}) {
        for (const double roundness : {0.0, 0.03, 0.3, 0.6, 0.9}) {
            const lens::Iris iris = lens::makeIris({blades, 10.0, roundness});
            double worst = 0;
            for (int k = 0; k < 20000; ++k) {
                const double ax = uniform(), ay = uniform(), bx = uniform(), by = uniform();
                const double qa = lens::irisRadius(iris, ax, ay),
                             qb = lens::irisRadius(iris, bx, by);
                const double qm = lens::irisRadius(iris, (ax + bx) / 2, (ay + by) / 2);
                worst = std::max(worst, qm - std::max(qa, qb));
            }
            if (iris.convex) {
                EXPECT_LE(worst, 1e-12) << blades << " blades, roundness " << roundness;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 25);
    // A 3-bladed iris barely rounded bows inward between its corners: flagged non-convex.
    const lens::Iris bowed = lens::makeIris({3, 0.0, 0.03});
    EXPECT_FALSE(bowed.convex);
}

// `lens ghosts --json` as the library writes it: every figure of the report under its documented
// name, the direct image without surfaces, each field explained.
TEST(Lens, GhostReportJsonCarriesEveryFigure) {
    auto lens = parseLens(kSlow, "slow.json");
    ASSERT_TRUE(lens.ok()) << lens.error().message;
    GhostQuery q;
    q.angleXDeg = 1.0, q.ghostRays = 0;
    auto r = analyseGhosts(*lens, q);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const auto j = nlohmann::json::parse(ghostReportJson("slow", *r));
    EXPECT_EQ(j["lens"], "slow");
    EXPECT_EQ(j["focal_length_mm"].get<double>(), r->focalLength);
    EXPECT_FALSE(j["direct"].contains("surfaces"));
    ASSERT_EQ(j["ghosts"].size(), r->ghosts.size());
    for (std::size_t i = 0; i < r->ghosts.size(); ++i) {
        const GhostFigure& g = r->ghosts[i];
        const auto& row = j["ghosts"][i];
        EXPECT_EQ(row["surfaces"], nlohmann::json({g.first, g.second}));
        EXPECT_EQ(row["center"], nlohmann::json({g.centerX, g.centerY}));
        EXPECT_EQ(row["radius90_mm"].get<double>(), g.radius90);
        EXPECT_EQ(row["intensity"][1].get<double>(), g.intensity[1]);
        for (const auto& [key, value] : row.items())
            EXPECT_TRUE(j["fields"].contains(key)) << key << " is not explained";
    }
}
