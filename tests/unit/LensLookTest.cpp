// SPDX-License-Identifier: Apache-2.0
// A lens saved from memory (lensToJson) and an artist's look per ghost (ghost_pairs): every
// shipped lens reads back to itself, a pair's gain and tint scale exactly that ghost, and bad
// pairs are refused with their field.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "flarekit/Lens.h"

namespace flarekit {
namespace {

void expectSameLens(const Lens& a, const Lens& b, const std::string& name) {
    EXPECT_EQ(a.name, b.name) << name;
    EXPECT_EQ(a.source, b.source) << name;
    EXPECT_EQ(a.fNumber, b.fNumber) << name;
    EXPECT_EQ(a.patentFocalLength, b.patentFocalLength) << name;
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size()) << name;
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
        const LensSurface &s = a.surfaces[i], &t = b.surfaces[i];
        EXPECT_EQ(s.radius, t.radius) << name << " " << i;
        EXPECT_EQ(s.thickness, t.thickness) << name << " " << i;
        EXPECT_EQ(s.nd, t.nd) << name << " " << i;
        EXPECT_EQ(s.vd, t.vd) << name << " " << i;
        EXPECT_EQ(s.semiAperture, t.semiAperture) << name << " " << i;
        EXPECT_EQ(s.stop, t.stop) << name << " " << i;
        ASSERT_EQ(s.coating.layers.size(), t.coating.layers.size()) << name << " " << i;
        for (std::size_t k = 0; k < s.coating.layers.size(); ++k) {
            EXPECT_EQ(s.coating.layers[k].n, t.coating.layers[k].n) << name << " " << i;
            EXPECT_EQ(s.coating.layers[k].thicknessNm, t.coating.layers[k].thicknessNm) << name;
        }
    }
    EXPECT_EQ(a.aperture.blades, b.aperture.blades) << name;
    EXPECT_EQ(a.aperture.rotationDeg, b.aperture.rotationDeg) << name;
    EXPECT_EQ(a.aperture.roundness, b.aperture.roundness) << name;
    EXPECT_EQ(a.sensor.width, b.sensor.width) << name;
    EXPECT_EQ(a.sensor.height, b.sensor.height) << name;
    ASSERT_EQ(a.ghostPairs.size(), b.ghostPairs.size()) << name;
    for (std::size_t i = 0; i < a.ghostPairs.size(); ++i) {
        EXPECT_EQ(a.ghostPairs[i].first, b.ghostPairs[i].first) << name;
        EXPECT_EQ(a.ghostPairs[i].second, b.ghostPairs[i].second) << name;
        EXPECT_EQ(a.ghostPairs[i].gain, b.ghostPairs[i].gain) << name;
        EXPECT_EQ(a.ghostPairs[i].tint, b.ghostPairs[i].tint) << name;
    }
}

TEST(LensLook, EveryShippedLensReadsBackFromItsSavedJson) {
    for (const std::string& name : lensNames()) {
        auto lens = loadLens(name);
        ASSERT_TRUE(lens.ok()) << name;
        // Edits of every kind the studio makes: a surface, the iris, a cemented surface's own
        // coating, a ghost's look.
        Lens edited = *lens;
        edited.surfaces[0].radius *= 1.01;
        edited.surfaces[1].coating = {};
        edited.aperture.blades = 7, edited.aperture.roundness = 0.25;
        std::vector<int> reflecting;  // surfaces that are not the stop
        for (int i = 0; i < int(lens->surfaces.size()); ++i)
            if (!lens->surfaces[std::size_t(i)].stop) reflecting.push_back(i);
        edited.ghostPairs = {{reflecting[3], reflecting[1], 2.5, {1.f, 0.5f, 0.25f}},
                             {reflecting[4], reflecting[2], 0.0, {1.f, 1.f, 1.f}}};
        for (const Lens& l : {*lens, edited}) {
            const std::string text = lensToJson(l);
            auto back = parseLens(text, l.name);
            ASSERT_TRUE(back.ok()) << name << ": " << back.error().message << "\n" << text;
            expectSameLens(l, *back, name);
            EXPECT_EQ(lensToJson(*back), text) << name;
        }
    }
}

//! The ghosts layer's channel sums of one light on the axis, the brightest ghost alone.
std::array<double, 3> oneGhostSums(const Lens& lens) {
    LensRenderOptions o;
    o.ghosts = 1, o.starburst = 0, o.glare = 0, o.gridSide = 32;
    o.ghostLevel = GhostLevel::Physical;
    LensLight light;
    light.x = 150, light.y = 90, light.energy = {1e6, 1e6, 1e6};
    auto layers = renderLensFlare(lens, 320, 240, {light}, o);
    EXPECT_TRUE(layers.ok());
    std::array<double, 3> sum{};
    if (!layers.ok()) return sum;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const Rgba& p = layers->ghosts.at(x, y);
            sum[0] += p.r, sum[1] += p.g, sum[2] += p.b;
        }
    return sum;
}

TEST(LensLook, APairsGainAndTintScaleExactlyItsGhost) {
    auto lens = loadLens("angenieux-double-gauss");
    ASSERT_TRUE(lens.ok());
    auto drawn = ghostsOnImage(*lens, 320, 240, Point{150, 90}, 1);
    ASSERT_TRUE(drawn.ok() && !drawn->empty());
    const GhostOnImage& brightest = drawn->front();
    const auto plain = oneGhostSums(*lens);
    ASSERT_GT(plain[1], 0.0);

    Lens looked = *lens;
    looked.ghostPairs = {{brightest.first, brightest.second, 2.0, {1.f, 0.5f, 0.f}}};
    const auto sums = oneGhostSums(looked);
    EXPECT_NEAR(sums[0], 2.0 * plain[0], 1e-4 * plain[0]);
    EXPECT_NEAR(sums[1], 1.0 * plain[1], 1e-4 * plain[1]);
    EXPECT_EQ(sums[2], 0.0);

    // Another pair's look leaves this ghost as it was.
    Lens other = *lens;
    other.ghostPairs = {{brightest.first + 1, brightest.first, 9.0, {1.f, 1.f, 1.f}}};
    if (other.surfaces[std::size_t(brightest.first + 1)].stop) ++other.ghostPairs[0].first;
    const auto same = oneGhostSums(other);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(same[std::size_t(c)], plain[std::size_t(c)]) << c;
}

std::string withPairs(const std::string& pairs) {
    auto lens = loadLens("angenieux-double-gauss");
    std::string text = lensToJson(*lens);
    return text.substr(0, text.rfind('}')) + ", \"ghost_pairs\": " + pairs + "}";
}

TEST(LensLook, BadGhostPairsAreRefusedWithTheirField) {
    const std::pair<const char*, const char*> cases[] = {
        {R"([{"surfaces": [3, 5]}])", "ghost_pairs[0].surfaces: expected [first, second] with"},
        {R"([{"surfaces": [15, 3]}])", "ghost_pairs[0].surfaces: expected [first, second] with"},
        {R"([{"surfaces": [9, 7]}])", "is the stop, which never reflects"},
        {R"([{"surfaces": [4, 2]}, {"surfaces": [4, 2], "gain": 2}])", "is already given"},
        {R"([{"surfaces": [4, 2], "gain": -1}])", "ghost_pairs[0].gain: expected"},
        {R"([{"surfaces": [4, 2], "tint": [1, 2]}])", "ghost_pairs[0].tint: expected"},
        {R"([{"surfaces": [4, 2], "colour": [1, 1, 1]}])", "ghost_pairs[0].colour: unknown key"},
        {R"([{"surfaces": "4,2"}])", "ghost_pairs[0].surfaces: expected [first, second]"},
        {R"({"surfaces": [4, 2]})", "ghost_pairs: expected an array"},
    };
    for (const auto& [pairs, expected] : cases) {
        auto lens = parseLens(withPairs(pairs), "my.json");
        ASSERT_FALSE(lens.ok()) << pairs;
        EXPECT_NE(lens.error().message.find(expected), std::string::npos)
            << pairs << ": " << lens.error().message;
        EXPECT_EQ(lens.error().message.find('\n'), std::string::npos);
    }
    Lens edited = *loadLens("angenieux-double-gauss");
    edited.surfaces[3].thickness = -30;
    const Status s = validateLens(edited, "studio lens");
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("studio lens: surfaces[3].thickness"), std::string::npos)
        << s.error().message;
}

}  // namespace
}  // namespace flarekit
