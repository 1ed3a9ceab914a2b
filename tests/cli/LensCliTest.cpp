// SPDX-License-Identifier: Apache-2.0
// flarekit lens as a user runs it: the ghosts report's JSON contract, a render with its layers
// (the composite is the input plus the flare layer), and bad input in one line with exit 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "Cli.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

TEST(LensCli, GhostsJsonFollowsTheContract) {
    const CliResult r = runCli({"lens", "ghosts", "nikon-zoom-80-200", "--angle", "3,1", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["lens"], "nikon-zoom-80-200");
    EXPECT_NEAR(j["focal_length_mm"].get<double>(), 57.206, 0.01);
    // The direct image of a source at (tan 3, tan 1) lands near f (tan X, tan Y).
    const double f = j["focal_length_mm"].get<double>();
    EXPECT_NEAR(j["direct"]["center"][0].get<double>(), f * std::tan(3 * M_PI / 180),
                0.02 * f * 0.05);
    EXPECT_NEAR(j["direct"]["center"][1].get<double>(), f * std::tan(1 * M_PI / 180),
                0.02 * f * 0.05);
    const auto& ghosts = j["ghosts"];
    // 22 surfaces, one of them the stop, 21 reflecting; cemented pairs still reflect a little.
    ASSERT_EQ(ghosts.size(), 21u * 20u / 2u);
    double last = 1e9;
    for (const auto& g : ghosts) {
        ASSERT_EQ(g["surfaces"].size(), 2u);
        EXPECT_GT(g["surfaces"][0].get<int>(), g["surfaces"][1].get<int>());
        EXPECT_NE(g["surfaces"][0].get<int>(), 17);  // the stop never reflects
        EXPECT_NE(g["surfaces"][1].get<int>(), 17);
        const double sum = g["intensity"][0].get<double>() + g["intensity"][1].get<double>() +
                           g["intensity"][2].get<double>();
        EXPECT_LE(sum, last + 1e-15);
        last = sum;
        EXPECT_GE(g["radius_mm"].get<double>(), 0.0);
        // The robust figures: percentile radii within the farthest ray, shares within [0, 1].
        const double r50 = g["radius50_mm"].get<double>(), r90 = g["radius90_mm"].get<double>();
        EXPECT_LE(r50, r90);
        EXPECT_LE(r90, 2 * g["radius_mm"].get<double>() + 1e-9);
        for (const char* share : {"on_sensor", "beam_share"}) {
            EXPECT_GE(g[share].get<double>(), 0.0) << share;
            EXPECT_LE(g[share].get<double>(), 1.0) << share;
        }
    }
    // The JSON says which field is which.
    for (const char* field : {"center", "radius_mm", "radius50_mm", "radius90_mm", "on_sensor",
                              "beam_share", "intensity"})
        EXPECT_TRUE(j["fields"].contains(field)) << field;
}

TEST(LensCli, GhostsMarksGhostsMostlyOffTheSensor) {
    // The Takumar at 6 degrees has wide ghosts most of whose rays miss its sensor; the table
    // marks them, and their share on the sensor agrees with the JSON's.
    const CliResult text =
        runCli({"lens", "ghosts", "asahi-takumar-50", "--angle", "6,-3", "--ghost-rays", "4096"});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    const CliResult json = runCli({"lens", "ghosts", "asahi-takumar-50", "--angle", "6,-3",
                                   "--ghost-rays", "4096", "--json"});
    ASSERT_EQ(json.exitCode, 0) << json.err;
    const auto j = nlohmann::json::parse(json.out);
    int off = 0;
    for (const auto& g : j["ghosts"]) off += g["on_sensor"].get<double>() < 0.5;
    EXPECT_GE(off, 1);
    std::size_t marked = 0;
    for (std::size_t at = text.out.find("mostly off sensor"); at != std::string::npos;
         at = text.out.find("mostly off sensor", at + 1))
        ++marked;
    EXPECT_EQ(marked, std::size_t(off));
    // --ghost-rays is checked against its range.
    const CliResult bad = runCli({"lens", "ghosts", "asahi-takumar-50", "--ghost-rays", "-1"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--ghost-rays"), std::string::npos) << bad.err;
}

TEST(LensCli, RenderWritesTheCompositeAndItsLayers) {
    TempDir dir;
    const std::string in = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";
    const CliResult r = runCli({"lens", "render", "kodak-petzval", in, "-o", dir.file("out.exr"),
                                "--layers", dir.file("layers"), "--ghosts", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto input = readImage(in), out = readImage(dir.file("out.exr"));
    auto flare = readImage(dir.file("layers/flare.exr"));
    ASSERT_TRUE(input.ok() && out.ok() && flare.ok());
    for (const char* layer : {"ghosts.exr", "starburst.exr", "glare.exr"})
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("layers/") + layer))) << layer;
    // out = input + flare, to the precision of the half-float files.
    double worst = 0, flareSum = 0;
    for (int y = 0; y < out->image.height(); y += 3)
        for (int x = 0; x < out->image.width(); x += 3) {
            const Rgba &o = out->image.at(x, y), &i = input->image.at(x, y),
                       &f = flare->image.at(x, y);
            const double expect = i.g + f.g;
            worst = std::max(worst, std::fabs(o.g - expect) / std::max(1e-3, expect));
            flareSum += f.g;
        }
    EXPECT_LT(worst, 2e-3);
    EXPECT_GT(flareSum, 0.0);
}

TEST(LensCli, BadInputIsOneLineAndExitTwo) {
    TempDir dir;
    const auto rejected = [&](const std::vector<std::string>& args, const std::string& mention) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    };
    const std::string bad = dir.file("bad.json");
    std::ofstream(bad)
        << R"({"surfaces": [{"radius": 50, "thickness": 5, "n_d": 1.5, "semi_aperture": 10},
        {"radius": -50, "thickness": 40, "semi_aperture": 10}]})";
    rejected({"lens", "ghosts", bad},
             "bad.json: surfaces: expected exactly one surface with \"stop\"");
    rejected({"lens", "ghosts", "no-such-lens"}, "lenses preset 'no-such-lens'");
    // A long glass barrel: at 60 degrees every ray, direct or reflected, leaves through its
    // side (a real lens passes some ghost rays even at 88 degrees).
    const std::string barrel = dir.file("barrel.json");
    std::ofstream(barrel)
        << R"({"surfaces": [{"radius": 0, "thickness": 100, "n_d": 1.5, "semi_aperture": 5},
        {"radius": 0, "thickness": 1, "semi_aperture": 5},
        {"stop": true, "thickness": 50, "semi_aperture": 2}]})";
    rejected({"lens", "ghosts", barrel, "--angle", "60,0"}, "no ray reaches the sensor");
    rejected({"lens", "ghosts", "nikon-zoom-80-200", "--f-number", "1.4"},
             "can only be stopped down");
    const std::string in = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";
    rejected({"lens", "render", "kodak-petzval", in, "-o", dir.file("o.png"), "--spectral", "1000"},
             "--spectral");
    rejected({"lens", "render", "kodak-petzval", in, "-o", dir.file("o.png"), "--spectral", "2"},
             "--spectral");
    rejected({"lens", "render", bad, in, "-o", dir.file("o.png")}, "bad.json");
    rejected({"lens", "render", "kodak-petzval", in, "-o", dir.file("o.png"), "--dirt-file",
              dir.file("no-such-dirt.png")},
             "no-such-dirt.png");
    rejected({"lens", "render", "kodak-petzval", in, "-o", dir.file("o.png"), "--dirt-file", bad},
             "bad.json");
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
}

TEST(LensCli, BakeWritesAPresetApplyUsesAndSheetDrawsTheLens) {
    TempDir dir;
    const std::string preset = dir.file("takumar.json");
    CliResult r = runCli({"lens", "bake", "asahi-takumar-50", "-o", preset, "--ghosts", "8"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"presets", "--check", preset});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"apply", std::string(FLAREKIT_SAMPLES) + "/sunset.png", "-o", dir.file("a.png"),
                "--preset", preset});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"lens", "sheet", "kodak-petzval", "-o", dir.file("sheet.png"), "--width", "800"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto sheet = readImage(dir.file("sheet.png"));
    ASSERT_TRUE(sheet.ok());
    EXPECT_EQ(sheet->image.width(), 800);
    EXPECT_EQ(sheet->image.height(), 450);
    r = runCli({"lens", "sheet", "kodak-petzval", "-o", dir.file("bad.png"), "--width", "10"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

#if FLAREKIT_HAS_GL
TEST(LensCli, GlBackendDrawsTheSameGhosts) {
    TempDir dir;
    const std::string in = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";
    for (const char* backend : {"cpu", "gl"}) {
        const CliResult r = runCli({"lens", "render", "asahi-takumar-50", in, "-o",
                                    dir.file(std::string(backend) + ".exr"), "--backend", backend,
                                    "--layers", dir.file(backend), "--ghosts", "12"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    auto cpu = readImage(dir.file("cpu/ghosts.exr")), gl = readImage(dir.file("gl/ghosts.exr"));
    ASSERT_TRUE(cpu.ok() && gl.ok());
    double sumCpu = 0, sumGl = 0;
    for (std::size_t i = 0; i < cpu->image.pixelCount() * 4; ++i) {
        if (i % 4 == 3) continue;
        sumCpu += cpu->image.data()[i], sumGl += gl->image.data()[i];
    }
    ASSERT_GT(sumCpu, 0.0);
    // The layers are half-float files: the sums agree far inside their rounding.
    EXPECT_NEAR(sumGl, sumCpu, 1e-3 * sumCpu);
}
#endif

TEST(LensCli, FlagsAreSpeltWithHyphensAndTheOldUnderscoreSpellingStillWorks) {
    TempDir dir;
    const std::string in = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
    const auto render = [&](const std::string& name, const std::vector<std::string>& flags) {
        std::vector<std::string> args = {"lens", "render",       "kodak-petzval", in,
                                         "-o",   dir.file(name), "--ghosts",      "4"};
        args.insert(args.end(), flags.begin(), flags.end());
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return slurp(dir.file(name));
    };
    const std::string hyphens =
        render("h.png", {"--ghost-gain", "300", "--starburst-size", "0.1", "--dirt-seed", "5"});
    const std::string underscores =
        render("u.png", {"--ghost_gain", "300", "--starburst_size", "0.1", "--dirt_seed", "5"});
    const std::string plain = render("p.png", {});
    EXPECT_FALSE(hyphens.empty());
    EXPECT_EQ(hyphens, underscores);  // the same options, bit for bit
    EXPECT_NE(hyphens, plain);        // and they did something
    // The old spelling is range-checked as the new one.
    const CliResult bad = runCli(
        {"lens", "render", "kodak-petzval", in, "-o", dir.file("b.png"), "--ghost_gain", "-1"});
    EXPECT_EQ(bad.exitCode, 2) << bad.err;
    // --help lists the hyphenated flag, and the underscore one only as a deprecation note.
    const CliResult help = runCli({"lens", "render", "--help"});
    EXPECT_NE(help.out.find("--ghost-gain FLOAT"), std::string::npos) << help.out;
    EXPECT_NE(help.out.find("(--ghost_gain still works; deprecated spelling)"), std::string::npos)
        << help.out;
    EXPECT_EQ(help.out.find("--ghost_gain FLOAT"), std::string::npos) << help.out;
}

// --ghost-level picks how bright the ghosts are drawn: the traced shares ("physical") times
// --ghost-gain, or the flux level (the default); physical x 1 is far fainter than the flux
// level on a photograph's sun. An unknown level is one line, exit 2, nothing written.
TEST(LensCli, GhostLevelFluxIsTheDefaultAndPhysicalIsTheTracedShare) {
    TempDir dir;
    const std::string in = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";
    const auto ghosts = [&](const std::string& name, const std::vector<std::string>& flags) {
        std::vector<std::string> args = {
            "lens",     "render",       "asahi-takumar-50", in, "-o", dir.file(name + ".exr"),
            "--layers", dir.file(name), "--starburst",      "0"};
        args.insert(args.end(), flags.begin(), flags.end());
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        auto layer = readImage(dir.file(name) + "/ghosts.exr");
        double sum = 0;
        if (layer.ok())
            for (std::size_t i = 0; i < layer->image.pixelCount(); ++i)
                sum += layer->image.data()[4 * i + 1];
        return sum;
    };
    const double flux = ghosts("default", {});
    const double named = ghosts("flux", {"--ghost-level", "flux"});
    const double physical = ghosts("physical", {"--ghost-level", "physical"});
    EXPECT_GT(flux, 0.0);
    EXPECT_NEAR(named, flux, 1e-6 * flux);
    EXPECT_GT(physical, 0.0);
    EXPECT_GT(flux, 10.0 * physical);
    const CliResult bad = runCli({"lens", "render", "asahi-takumar-50", in, "-o",
                                  dir.file("bad.exr"), "--ghost-level", "bright"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--ghost-level"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.exr")));
}
