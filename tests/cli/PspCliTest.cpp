// SPDX-License-Identifier: Apache-2.0
// flarekit psp as a user runs it: JSON, dumps, the naive mode, the demo, bad input.
#include <gtest/gtest.h>

#include <filesystem>

#include "Cli.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {
//! A w x h grey mask with columns [x0, x1) occluded.
std::string writeMask(const TempDir& dir, const std::string& name, int w, int h, int x0, int x1) {
    Image8 mask{w, h, 1, std::vector<std::uint8_t>(std::size_t(w * h), 0)};
    for (int y = 0; y < h; ++y)
        for (int x = std::max(0, x0); x < std::min(w, x1); ++x)
            mask.pixels[std::size_t(y * w + x)] = 255;
    const std::string path = dir.file(name);
    EXPECT_TRUE(writeImage8(path, mask).ok());
    return path;
}

void expectBadInput(const CliResult& r, const std::string& mention) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}
}  // namespace

TEST(CliPsp, BurnoutJsonDumpAndNaive) {
    TempDir dir;
    const std::string mask = writeMask(dir, "pole.png", 480, 272, 233, 240);  // 7 of the 14 columns
    auto r = runCli({"psp", "burnout", "--occluders", mask, "--sun", "240,100", "-o",
                     dir.file("out.png"), "--json", "--dump", dir.file("dump"), "--trace",
                     dir.file("trace.txt")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"coverage_byte\": 127"), std::string::npos)
        << r.out;  // the chain's taps are symmetric
    EXPECT_NE(r.out.find("\"clut_alpha\": 127"), std::string::npos) << r.out;
    auto frame = readImage8(dir.file("out.png"));
    ASSERT_TRUE(frame.ok());
    EXPECT_EQ(frame->width, 480);
    EXPECT_EQ(frame->height, 272);
    int dumped = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("dump")))
        dumped += e.path().extension() == ".png";
    EXPECT_EQ(dumped, 10);
    EXPECT_NE(slurp(dir.file("trace.txt")).find("CLOAD"), std::string::npos);
    auto naive = runCli({"psp", "burnout", "--occluders", mask, "--sun", "240,100", "-o",
                         dir.file("naive.png"), "--json", "--naive"});
    ASSERT_EQ(naive.exitCode, 0) << naive.err;
    EXPECT_NE(naive.out.find("\"clut_alpha\": 255"), std::string::npos) << naive.out;
}

TEST(CliPsp, RidgeRacerAndSunOffScreen) {
    TempDir dir;
    const std::string mask = writeMask(dir, "m.png", 480, 272, 0, 0);
    auto r = runCli({"psp", "ridge-racer", "--occluders", mask, "--sun", "100,50", "-o",
                     dir.file("rr.png"), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"coverage_byte\": 255"), std::string::npos) << r.out;
    auto off = runCli({"psp", "burnout", "--occluders", mask, "--sun", "-30,50", "-o",
                       dir.file("off.png"), "--json"});
    ASSERT_EQ(off.exitCode, 0) << off.err;
    EXPECT_NE(off.out.find("\"sun_in_frame\": false"), std::string::npos) << off.out;
    EXPECT_TRUE(std::filesystem::exists(dir.file("off.png")));
}

TEST(CliPsp, BadInputExitsTwoAndWritesNothing) {
    TempDir dir;
    const std::string small = writeMask(dir, "small.png", 320, 240, 0, 10);
    const std::string good = writeMask(dir, "good.png", 480, 272, 0, 10);
    const std::size_t before = dir.entries();
    expectBadInput(runCli({"psp", "burnout", "--occluders", small, "--sun", "240,100", "-o",
                           dir.file("o.png")}),
                   "480x272");
    expectBadInput(runCli({"psp", "burnout", "--occluders", dir.file("missing.png"), "--sun",
                           "240,100", "-o", dir.file("o.png")}),
                   "missing.png");
    expectBadInput(runCli({"psp", "burnout", "--occluders", good, "--sun", "240;100", "-o",
                           dir.file("o.png")}),
                   "--sun");
    expectBadInput(
        runCli({"psp", "burnout", "--occluders", good, "--sun", "1e9,5", "-o", dir.file("o.png")}),
        "sun");
    expectBadInput(runCli({"psp", "burnout", "--occluders", good, "--sun", "5,-1e30", "-o",
                           dir.file("o.png")}),
                   "sun");
    EXPECT_EQ(dir.entries(), before);
}

TEST(CliPsp, DemoWritesSideBySideFrames) {
    TempDir dir;
    auto r = runCli({"psp", "demo", "-o", dir.file("demo"), "--frames", "3"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto frame = readImage8(dir.file("demo/frame_0002.png"));
    ASSERT_TRUE(frame.ok());
    EXPECT_EQ(frame->width, 960);
    EXPECT_EQ(lineCount(slurp(dir.file("demo/coverage.csv"))), 4);
}
