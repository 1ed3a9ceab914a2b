// SPDX-License-Identifier: Apache-2.0
// The CLI used as users use it: real files in, files out, exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "Cli.h"
#include "RawFiles.h"
#include "flarekit/Blend.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

Image8 randomImage(int w, int h, int channels, unsigned seed) {
    std::mt19937 rng(seed);
    Image8 img{w, h, channels, std::vector<std::uint8_t>(std::size_t(w * h * channels))};
    for (auto& b : img.pixels) b = std::uint8_t(rng() & 0xFF);
    return img;
}

double meanAbsDiff(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixelCount() * 4; ++i) sum += std::abs(a.data()[i] - b.data()[i]);
    return sum / double(a.pixelCount());
}

}  // namespace

TEST(CliBlend, EveryModeIsBitExactOnFiles) {
    TempDir dir;
    const Image8 src = randomImage(97, 31, 4, 1), dst = randomImage(97, 31, 3, 2);
    ASSERT_TRUE(writeImage8(dir.file("s.png"), src).ok());
    ASSERT_TRUE(writeImage8(dir.file("d.png"), dst).ok());
    for (const char* mode : {"alpha", "alpha-shift", "premultiplied", "add"}) {
        const CliResult r = runCli({"blend", "--mode", mode, "--src", dir.file("s.png"), "--dst",
                                    dir.file("d.png"), "-o", dir.file(std::string(mode) + ".png")});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        auto out = readImage8(dir.file(std::string(mode) + ".png"));
        ASSERT_TRUE(out.ok());
        ASSERT_EQ(out->channels, 3);
        for (std::size_t i = 0; i < std::size_t(97 * 31); ++i) {
            const int a = src.pixels[i * 4 + 3];
            for (std::size_t c = 0; c < 3; ++c) {
                const int s = src.pixels[i * 4 + c], d = dst.pixels[i * 3 + c];
                int want = 0;
                if (std::string(mode) == "alpha") want = (s * a + d * (255 - a)) / 255;
                if (std::string(mode) == "alpha-shift") want = (s * a + d * (255 - a)) >> 8;
                if (std::string(mode) == "premultiplied")
                    want = s * a / 255 + ((d * (255 - a)) >> 8);
                if (std::string(mode) == "add") want = std::min(s + d, 255);
                ASSERT_EQ(out->pixels[i * 3 + c], want) << mode << " pixel " << i;
            }
        }
    }
}

TEST(CliBlend, SizeMismatchAndBadModeExitTwoWithoutOutput) {
    TempDir dir;
    ASSERT_TRUE(writeImage8(dir.file("s.png"), randomImage(8, 8, 4, 3)).ok());
    ASSERT_TRUE(writeImage8(dir.file("d.png"), randomImage(9, 8, 3, 4)).ok());
    CliResult r = runCli({"blend", "--mode", "alpha", "--src", dir.file("s.png"), "--dst",
                          dir.file("d.png"), "-o", dir.file("o.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("sizes differ"), std::string::npos) << r.err;
    r = runCli({"blend", "--mode", "multiply", "--src", dir.file("s.png"), "--dst",
                dir.file("d.png"), "-o", dir.file("o.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    ASSERT_TRUE(writeImage8(dir.file("rgb.png"), randomImage(9, 8, 3, 5)).ok());
    r = runCli({"blend", "--mode", "alpha", "--src", dir.file("rgb.png"), "--dst",
                dir.file("d.png"), "-o", dir.file("o.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("expected RGBA"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
    EXPECT_EQ(dir.entries(), 3u);
}

TEST(CliApply, AutoLightOnTheSampleAddsAFlare) {
    TempDir dir;
    const CliResult r =
        runCli({"apply", kSunset, "-o", dir.file("o.png"), "--light", "auto", "-v"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The sun's clipped glare, centred on the disc (930, 250) but cut by nothing above it and
    // by the horizon's glow below, is the one light.
    EXPECT_NE(r.out.find("flare at 930.0,25"), std::string::npos) << r.out;
    auto in = readImage(kSunset), out = readImage(dir.file("o.png"));
    ASSERT_TRUE(in.ok() && out.ok());
    EXPECT_GT(meanAbsDiff(in->image, out->image), 0.003);
    // The secondary at t = -1 (radius 65 px) lands at the mirrored point: brighter there.
    const int mx = 1280 - 930, my = 720 - 250;
    double added = 0;
    for (int y = my - 60; y < my + 60; ++y) {
        for (int x = mx - 60; x < mx + 60; ++x)
            added += out->image.at(x, y).r - in->image.at(x, y).r;
    }
    EXPECT_GT(added / (120.0 * 120.0), 0.02);
    EXPECT_EQ(dir.entries(), 1u);
}

TEST(CliApply, EveryShippedPresetAndFormatWorks) {
    TempDir dir;
    for (const char* preset :
         {"tanczos-classic", "sun-wide", "anamorphic", "hexagon-ghosts", "subtle", "starburst"}) {
        const CliResult r = runCli(
            {"apply", kSunset, "-o", dir.file(std::string(preset) + ".jpg"), "--preset", preset});
        EXPECT_EQ(r.exitCode, 0) << preset << ": " << r.err;
    }
    const CliResult hdr =
        runCli({"apply", kSunsetHdr, "-o", dir.file("hdr.exr"), "--light", "930,250"});
    ASSERT_EQ(hdr.exitCode, 0) << hdr.err;
    auto out = readImage(dir.file("hdr.exr"));
    ASSERT_TRUE(out.ok());
    EXPECT_TRUE(out->wasFloat);
    EXPECT_GT(out->image.at(930, 250).r, 50.f);  // HDR kept linear, flare added on top
    const CliResult tif = runCli({"apply", kSunset, "-o", dir.file("o.tif"), "--depth", "16"});
    EXPECT_EQ(tif.exitCode, 0) << tif.err;
}

// Far outside the frame there is nothing to measure: measured, no flare and a warning saying so;
// fixed, the preset's own flare. Coordinates past a million pixels are refused.
TEST(CliApply, ExplicitLightOutsideTheFrame) {
    TempDir dir;
    CliResult r = runCli({"apply", kSunset, "-o", dir.file("o.png"), "--light=-300,-200",
                          "--intensity", "2", "--flux-mode", "fixed"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto in = readImage(kSunset), out = readImage(dir.file("o.png"));
    EXPECT_GT(meanAbsDiff(in->image, out->image), 0.001);
    r = runCli({"apply", kSunset, "-o", dir.file("m.png"), "--light=-300,-200"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("--light -300,-200: nothing to measure there"), std::string::npos)
        << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    for (const char* far : {"--light=1e38,5", "--light=5,-2e6"}) {
        r = runCli({"apply", kSunset, "-o", dir.file("f.png"), far});
        EXPECT_EQ(r.exitCode, 2) << far;
        EXPECT_NE(r.err.find("expected pixel coordinates from -1000000 to 1000000"),
                  std::string::npos)
            << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("f.png")));
}

TEST(CliApply, NoLightWritesTheImageUnchangedWithAWarning) {
    TempDir dir;
    Image grey(64, 48);
    grey.fill({0.1f, 0.1f, 0.1f, 1.f});
    ASSERT_TRUE(writeImage(dir.file("grey.png"), grey).ok());
    const CliResult r = runCli({"apply", dir.file("grey.png"), "-o", dir.file("o.png")});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find(dir.file("grey.png").append(": peak luminance 0.100 is below")),
              std::string::npos)
        << r.err;
    auto a = readImage8(dir.file("grey.png")), b = readImage8(dir.file("o.png"));
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->pixels, b->pixels);
}

TEST(CliApply, KeepsAlpha) {
    TempDir dir;
    Image img(32, 32);
    img.fill({1.f, 1.f, 1.f, 0.5f});
    ASSERT_TRUE(
        writeImage(dir.file("a.png"), img, {SampleFormat::U8, true, true, nullptr, {}, {}}).ok());
    ASSERT_EQ(runCli({"apply", dir.file("a.png"), "-o", dir.file("o.png")}).exitCode, 0);
    auto out = readImage8(dir.file("o.png"));
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(out->channels, 4);
    EXPECT_EQ(out->pixels[3], 128);
}

TEST(CliElements, WritesALabelledSheet) {
    TempDir dir;
    const CliResult r = runCli(
        {"elements", "--preset", "hexagon-ghosts", "-o", dir.file("sheet.png"), "--cell", "128"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");  // labels drawn: no font warning
    auto sheet = readImage(dir.file("sheet.png"));
    ASSERT_TRUE(sheet.ok());
    EXPECT_EQ(sheet->image.width(), 4 * 128);
    EXPECT_EQ(sheet->image.height(), 3 * 128);  // 9 elements in rows of 4
}

TEST(CliPresets, ListsChecksAndDocuments) {
    CliResult r = runCli({"presets"});
    ASSERT_EQ(r.exitCode, 0);
    for (const char* name :
         {"tanczos-classic", "sun-wide", "anamorphic", "hexagon-ghosts", "subtle"}) {
        EXPECT_NE(r.out.find(name), std::string::npos) << name;
    }
    r = runCli({"presets", "--params"});
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("| `min_length` | rays |"), std::string::npos) << r.out;
    // docs/presets.md carries this reference verbatim: regenerate it when the table changes.
    EXPECT_NE(slurp(std::string(FLAREKIT_DOCS) + "/presets.md").find(r.out), std::string::npos)
        << "docs/presets.md is out of date: flarekit presets --params";
    r = runCli({"presets", "--postfx", "--params"});
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("| bloom | `levels` | 6 | [2, 12] |"), std::string::npos) << r.out;
    EXPECT_NE(slurp(std::string(FLAREKIT_DOCS) + "/postfx.md").find(r.out), std::string::npos)
        << "docs/postfx.md is out of date: scripts/update-docs.sh";
    r = runCli({"presets", "--check", "subtle"});
    EXPECT_EQ(r.exitCode, 0);
    r = runCli({"synth", "--params"});
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("| `lights_max` | 4 | [1, 64] |"), std::string::npos) << r.out;
    EXPECT_NE(slurp(std::string(FLAREKIT_DOCS) + "/synth.md").find(r.out), std::string::npos)
        << "docs/synth.md is out of date: scripts/update-docs.sh";
}

TEST(CliParams, NumericFlagsTakeRangeAndHelpFromTheParameterTables) {
    CliResult r = runCli({"demo", "--help"});
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("[1, 100000]"), std::string::npos) << r.out;  // --frames
    EXPECT_NE(r.out.find("edge fade width (shorter side)"), std::string::npos)
        << r.out;  // --guard-band
    TempDir dir;
    r = runCli({"demo", "-o", dir.file("d"), "--samples", "0"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--samples: expected an integer in [1, 4096], got 0"), std::string::npos)
        << r.err;
    r = runCli({"visibility", "no-scene.json", "--msaa", "3"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--msaa: expected one of 1, 2, 4, 8, got 3"), std::string::npos) << r.err;
    r = runCli({"postfx", "in.png", "-o", dir.file("o.png"), "--threshold", "-1"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--threshold: expected a number in [0, 10000], got -1"), std::string::npos)
        << r.err;
    r = runCli({"demo", "-o", dir.file("d"), "--frames", "2.5"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("expected an integer"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("d")));
}

TEST(CliHelp, EverySubcommandHasHelp) {
    for (const char* sub :
         {"blend", "apply", "elements", "presets", "visibility", "render", "demo"}) {
        const CliResult r = runCli({sub, "--help"});
        EXPECT_EQ(r.exitCode, 0) << sub;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub << ": " << r.out;
    }
    EXPECT_EQ(runCli({"frobnicate"}).exitCode, 2);
    EXPECT_EQ(runCli({}).exitCode, 2);
}

TEST(CliVisibility, RaycastPrintsOneJsonObject) {
    const CliResult r =
        runCli({"visibility", std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json",
                "--method", "raycast", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineCount(r.out), 1);
    EXPECT_EQ(r.out.rfind("{\"method\": \"raycast\", \"coverage\": 1.000000, \"in_frame\": "
                          "1.000000, \"samples\": 16384",
                          0),
              0u)
        << r.out;
}

TEST(CliVisibility, HalfHiddenSunFromAFile) {
    TempDir dir;
    std::ofstream(dir.file("half.json")) << R"({"image": {"width": 640, "height": 360},
        "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]},
        "sun": {"direction": [0, 0, -1], "angular_radius_deg": 2},
        "objects": [{"type": "box", "min": [-100, -100, -30], "max": [0, 100, -20]}]})";
    const CliResult r = runCli({"visibility", dir.file("half.json"), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto at = r.out.find("\"coverage\": ");
    ASSERT_NE(at, std::string::npos);
    EXPECT_NEAR(std::stod(r.out.substr(at + 12)), 0.5, 0.005);
}

TEST(CliVisibility, BadSceneAndBadMethodExitTwo) {
    TempDir dir;
    std::ofstream(dir.file("bad.json")) << R"({"image": {"width": 640, "height": 360},
        "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]}, "sun": {"direction": [0, 0, -1]},
        "objects": [{"type": "sphere", "center": [0, 0, -5], "radius": "big"}]})";
    CliResult r = runCli({"visibility", dir.file("bad.json")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "flarekit: " + dir.file("bad.json") +
                         ": objects[0].radius: expected a positive number, got \"big\"\n");
    r = runCli({"visibility", std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json",
                "--method", "magic"});
    EXPECT_EQ(lineCount(r.err), 1);
    EXPECT_EQ(r.exitCode, 2);
    r = runCli({"visibility", dir.file("missing.json")});
    EXPECT_EQ(r.exitCode, 2);
}

FLAREKIT_GL_TEST(CliVisibility, EveryGpuMethodPrintsOneJsonObject) {
    const std::string scene = std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json";
    for (const char* method : {"readback", "pbo", "query", "texture-mask", "texture-mask-screen",
                               "burnout", "compute"}) {
        const CliResult r = runCli({"visibility", scene, "--method", method, "--json"});
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
        EXPECT_EQ(
            r.out.rfind(std::string("{\"method\": \"") + method + "\", \"coverage\": 1.000000", 0),
            0u)
            << r.out;
        EXPECT_NE(r.out.find("\"latency_frames\": "), std::string::npos) << r.out;
    }
}

FLAREKIT_GL_TEST(CliRender, RendersTheContractSceneWithAFlare) {
    TempDir dir;
    const std::string scene = std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json";
    CliResult r = runCli({"render", scene, "-o", dir.file("f.png"), "-v"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("coverage 1.0000"), std::string::npos) << r.out;
    r = runCli({"render", scene, "-o", dir.file("f.exr"), "--no-flare"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto png = readImage(dir.file("f.png")), exr = readImage(dir.file("f.exr"));
    ASSERT_TRUE(png.ok() && exr.ok());
    EXPECT_EQ(png->image.width(), 640);
    EXPECT_TRUE(exr->wasFloat);
    float peak = 0;
    for (std::size_t i = 0; i < exr->image.pixelCount(); ++i)
        peak = std::max(peak, exr->image.data()[i * 4]);
    EXPECT_NEAR(peak, 2400.f, 2.f);  // the sun disc, linear HDR (half float: 1 part in 2048)
    r = runCli({"render", dir.file("missing.json"), "-o", dir.file("x.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1);
}

FLAREKIT_GL_TEST(CliRender, GpuMethodsDrawTheFlareTheRaycastPathDraws) {
    TempDir dir;
    const std::string scene = std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json";
    CliResult r = runCli({"render", scene, "-o", dir.file("raycast.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto reference = readImage(dir.file("raycast.exr"));
    ASSERT_TRUE(reference.ok());
    for (const char* method : {"readback", "pbo", "query", "texture-mask", "texture-mask-screen",
                               "burnout", "compute"}) {
        const std::string out = dir.file(std::string(method) + ".exr");
        r = runCli({"render", scene, "-o", out, "--method", method, "-v"});
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
        EXPECT_NE(r.out.find("coverage 1.0000 (" + std::string(method) + ")"), std::string::npos)
            << r.out;
        auto image = readImage(out);
        ASSERT_TRUE(image.ok()) << method;
        // The sun is fully visible, so the GPU flare (coverage read in the vertex shader) must
        // carry the CPU flare's light: same total within the bilinear placement's 1%.
        double gpu = 0, cpu = 0;
        for (std::size_t i = 0; i < image->image.pixelCount() * 4; ++i) {
            if (i % 4 == 3) continue;
            gpu += image->image.data()[i];
            cpu += reference->image.data()[i];
        }
        EXPECT_NEAR(gpu / cpu, 1.0, 0.01) << method;
    }
    r = runCli({"render", scene, "-o", dir.file("x.png"), "--method", "magic"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1);
    EXPECT_NE(r.err.find("texture-mask"), std::string::npos) << r.err;  // lists what is available
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

FLAREKIT_GL_TEST(CliDemo, GpuMethodRunsFlareFilterAndToneMapOnTheGpu) {
    TempDir dir;
    const std::string out = dir.file("demo");
    CliResult r = runCli({"demo", "-o", out, "--frames", "24", "--fps", "3", "--size", "160x90",
                          "--method", "compute", "--no-video"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("method compute"), std::string::npos) << r.out;
    const std::string csv = slurp(out + "/coverage.csv");
    EXPECT_EQ(lineCount(csv), 25);
    // The drive's story holds with the GPU method too: some frames hidden (tunnel), some clear.
    int hidden = 0, clear = 0;
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
        const double raw = std::stod(line.substr(line.find(',', line.find(',') + 1) + 1));
        hidden += raw == 0.0;
        clear += raw > 0.99;
    }
    EXPECT_GE(hidden, 3);
    EXPECT_GE(clear, 3);
}

FLAREKIT_GL_TEST(CliDemo, WritesFramesLogStripAndVideo) {
    TempDir dir;
    const std::string out = dir.file("demo");  // created by the command
    CliResult r = runCli({"demo", "-o", out, "--frames", "6", "--size", "160x90"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("demo: 6/6 (100%)"), std::string::npos)
        << r.err;  // plain progress off a TTY
    for (int i = 1; i <= 6; ++i) {
        auto frame = readImage(out + "/frame_000" + std::to_string(i) + ".png");
        ASSERT_TRUE(frame.ok()) << i;
        EXPECT_EQ(frame->image.width(), 160);
        EXPECT_EQ(frame->image.height(), 90);
    }
    EXPECT_FALSE(std::filesystem::exists(out + "/frame_0007.png"));
    const std::string csv = slurp(out + "/coverage.csv");
    EXPECT_EQ(lineCount(csv), 7);  // header + 6 frames
    EXPECT_EQ(csv.rfind("frame,time_s,coverage_raw,coverage_smoothed", 0), 0u);
    auto strip = readImage(out + "/strip.png");
    ASSERT_TRUE(strip.ok());
    EXPECT_EQ(strip->image.width(), 3 * 160);
    // The install script installs ffmpeg, so the video is part of the contract here.
    ASSERT_TRUE(std::filesystem::exists(out + "/demo.mp4")) << r.err;
    EXPECT_GT(std::filesystem::file_size(out + "/demo.mp4"), 1000u);
    EXPECT_FALSE(std::filesystem::exists(out + "/demo.mp4.partial.mp4"));
}

TEST(CliDemo, BadOptionsExitTwoWithOneLine) {
    TempDir dir;
    const std::string file = dir.file("plain-file");
    std::ofstream(file) << "x";
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"demo", "-o", dir.file("a"), "--size", "160by90"},
          {"demo", "-o", dir.file("a"), "--size", "4x4"},
          {"demo", "-o", dir.file("a"), "--method", "telepathy"},
          {"demo", "-o", dir.file("a"), "--frames", "0"},
          {"demo", "-o", dir.file("a"), "--guard-band", "2"},
          {"demo", "-o", file + "/sub"},
          {"demo", "-o", file}}) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << args.back() << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("a")));  // nothing created on bad input
}

// The shipped sample scenes show occlusion on the first try: a sun low through tree crowns
// (partly hidden), half behind a building's edge, and below the horizon (hidden by the ground).
TEST(CliScenes, SampleScenesShowOcclusion) {
    const std::string dir = std::string(FLAREKIT_SAMPLES) + "/scenes/";
    struct Expect {
        const char* scene;
        double lo, hi;
    };
    for (const Expect& e : {Expect{"sun-behind-trees.json", 0.1, 0.5},
                            Expect{"sun-at-building-edge.json", 0.45, 0.55},
                            Expect{"sun-below-horizon.json", 0.0, 0.0}}) {
        const CliResult r = runCli({"visibility", dir + e.scene, "--json"});
        ASSERT_EQ(r.exitCode, 0) << e.scene << ": " << r.err;
        const auto at = r.out.find("\"coverage\": ");
        ASSERT_NE(at, std::string::npos) << r.out;
        const double coverage = std::stod(r.out.substr(at + 12));
        EXPECT_GE(coverage, e.lo) << e.scene;
        EXPECT_LE(coverage, e.hi) << e.scene;
    }
}

// An install at any prefix finds its presets beside the executable: bin/flarekit and
// share/flarekit/presets moved together somewhere else still work.
TEST(CliPresets, FoundBesideTheExecutableAfterAnInstallElsewhere) {
    TempDir dir;
    namespace fs = std::filesystem;
    fs::create_directories(dir.file("prefix/bin"));
    fs::create_directories(dir.file("prefix/share/flarekit/presets"));
    fs::copy_file(FLAREKIT_CLI, dir.file("prefix/bin/flarekit"));
    std::ofstream(dir.file("prefix/share/flarekit/presets/only-here.json"))
        << R"({"name": "only-here", "description": "installed beside the binary", "elements": [{"type": "glow"}]})";
    const std::string cmd = quote(dir.file("prefix/bin/flarekit")) + " presets >" +
                            quote(dir.file("out.txt")) + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_NE(slurp(dir.file("out.txt")).find("only-here"), std::string::npos)
        << slurp(dir.file("out.txt"));
}

// --depth half or float into a format that only holds integers is refused, not downgraded.
TEST(CliApply, FloatDepthIntoAnIntegerFormatIsRefused) {
    TempDir dir;
    const CliResult r = runCli({"apply", kSunsetHdr, "-o", dir.file("o.png"), "--depth", "half"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--depth half: a '.png' file holds 8, 16 samples"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
    EXPECT_EQ(runCli({"apply", kSunsetHdr, "-o", dir.file("o.tif"), "--depth", "float"}).exitCode,
              0);
}

// Every depth a format cannot hold is refused before any work (a 4K job would otherwise run to
// the end and fail at the write, or write float samples for --depth 8), and nothing is written.
TEST(CliApply, EveryDepthAFormatCannotHoldIsRefusedBeforeAnyWork) {
    TempDir dir;
    for (const auto& [out, depth] :
         {std::pair{"o.exr", "8"}, std::pair{"o.exr", "16"}, std::pair{"o.jpg", "16"},
          std::pair{"o.hdr", "8"}, std::pair{"o.hdr", "16"}, std::pair{"o.jpg", "float"}}) {
        const CliResult r = runCli({"apply", kSunsetHdr, "-o", dir.file(out), "--depth", depth});
        EXPECT_EQ(r.exitCode, 2) << out << " " << depth << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(std::string("--depth ") + depth + ": a '"), std::string::npos)
            << r.err;
        // Refused before the image is read: no "flarekit: reading" detail, no file.
        EXPECT_FALSE(std::filesystem::exists(dir.file(out))) << out;
    }
    EXPECT_EQ(dir.entries(), 0u);
}

// Start-up: OpenImageIO and its 263 libraries are loaded only for a format flarekit does not
// run itself. The dynamic loader's own log (LD_DEBUG=files) names every library it opens.
TEST(Startup, JobsOnPngJpegTiffAndExrNeverLoadOpenImageIo) {
    TempDir dir;
    auto loads = [&](const std::vector<std::string>& args) {
        setenv("LD_DEBUG", "files", 1);
        const CliResult r = runCli(args);
        unsetenv("LD_DEBUG");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.err.find("libOpenImageIO") != std::string::npos;
    };
    EXPECT_FALSE(loads({"--version"}));
    EXPECT_FALSE(loads({"apply", kSunset, "-o", dir.file("a.jpg")}));
    EXPECT_FALSE(loads({"postfx", kSunsetHdr, "-o", dir.file("b.tif")}));
    EXPECT_FALSE(loads({"blend", "--src", dir.file("a.jpg"), "--dst", dir.file("a.jpg"), "--mode",
                        "add", "-o", dir.file("c.png")}));
    EXPECT_FALSE(loads({"postfx", dir.file("b.tif"), "-o", dir.file("d.exr")}));
    // ... and it is loaded, and works, for one it does not.
    EXPECT_TRUE(loads({"apply", kSunset, "-o", dir.file("e.bmp")}));
    EXPECT_TRUE(loads({"apply", dir.file("e.bmp"), "-o", dir.file("f.png")}));
}

// The CLI's EXR ZIP chunks are deflated and inflated by libdeflate: the loader binds
// libOpenEXR's zlib calls to the flarekit executable (src/core/codecs/ZlibOnLibdeflate.cpp).
TEST(Startup, OpenExrZlibCallsBindToTheExecutable) {
    TempDir dir;
    setenv("LD_DEBUG", "bindings", 1);
    const CliResult r =
        runCli({"--exr-compression", "zip", "postfx", kSunsetHdr, "-o", dir.file("z.exr")});
    unsetenv("LD_DEBUG");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* symbol : {"`compress2'", "`uncompress'"}) {
        std::istringstream log(r.err);
        std::string line, binding;
        while (std::getline(log, line))
            if (line.find("libOpenEXR-") != std::string::npos &&
                line.find(symbol) != std::string::npos)
                binding = line;
        EXPECT_NE(binding.find("/flarekit [0]"), std::string::npos) << symbol << ": " << binding;
    }
}

TEST(CliFormats, CompressionOptionsChooseTheEncoderAndRefuseBadValues) {
    TempDir dir;
    auto compressionOf = [](const std::string& path) {
        auto in = OIIO::ImageInput::open(path);
        return in ? std::string(in->spec().get_string_attribute("compression"))
                  : std::string("unreadable");
    };
    // An EXR input's own compression is kept; any other input gets PIZ.
    ASSERT_EQ(runCli({"postfx", kSunsetHdr, "-o", dir.file("a.exr")}).exitCode, 0);
    EXPECT_EQ(compressionOf(dir.file("a.exr")), compressionOf(kSunsetHdr));
    ASSERT_EQ(runCli({"postfx", kSunset, "-o", dir.file("a2.exr")}).exitCode, 0);
    EXPECT_EQ(compressionOf(dir.file("a2.exr")), "piz");
    ASSERT_EQ(runCli({"--exr-compression", "zip", "postfx", kSunsetHdr, "-o", dir.file("b.exr")})
                  .exitCode,
              0);
    EXPECT_EQ(compressionOf(dir.file("b.exr")), "zip");
    ASSERT_EQ(
        runCli({"apply", kSunset, "-o", dir.file("c0.png"), "--png-compression", "0"}).exitCode, 0);
    ASSERT_EQ(
        runCli({"apply", kSunset, "-o", dir.file("c9.png"), "--png-compression", "9"}).exitCode, 0);
    EXPECT_GT(std::filesystem::file_size(dir.file("c0.png")),
              2 * std::filesystem::file_size(dir.file("c9.png")));
    // --exr-zip-level: 0 stores the halves, 9 deflates harder than the default 1.
    for (const char* level : {"0", "1", "9"}) {
        ASSERT_EQ(runCli({"--exr-compression", "zip", "--exr-zip-level", level, "postfx",
                          kSunsetHdr, "-o", dir.file(std::string("z") + level + ".exr")})
                      .exitCode,
                  0);
    }
    EXPECT_GT(std::filesystem::file_size(dir.file("z0.exr")),
              std::filesystem::file_size(dir.file("z1.exr")));
    EXPECT_GT(std::filesystem::file_size(dir.file("z1.exr")),
              std::filesystem::file_size(dir.file("z9.exr")));
    for (const auto& bad : {std::vector<std::string>{"--exr-compression", "lzma"},
                            std::vector<std::string>{"--png-compression", "10"},
                            std::vector<std::string>{"--exr-zip-level", "-1"}}) {
        std::vector<std::string> args = {"apply", kSunset, "-o", dir.file("bad.png")};
        args.insert(args.end(), bad.begin(), bad.end());
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << bad[0];
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(bad[0]), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
    }
}
