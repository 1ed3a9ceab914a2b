// SPDX-License-Identifier: Apache-2.0
// Shots through the CLI: frames bit-identical however the range is chunked, a track's frames
// equal to single-image calls, lens render over a sequence, and every bad input of a shot.
#include <gtest/gtest.h>

#include "ShotFixtures.h"

using namespace flarekit;
using namespace flarekit::test;
using namespace flarekit::test::shot;

TEST(ShotCli, FramesAreBitIdenticalHoweverTheShotIsChunked) {
    TempDir in, whole, chunks;
    writeShot(in);
    ASSERT_EQ(runCli(shotArgs(in, whole.file("o.####.exr"))).exitCode, 0);
    for (const char* chunk : {"1-5", "6", "7-12:2", "8-12:2"}) {
        const CliResult r =
            runCli(with(shotArgs(in, chunks.file("o.####.exr")), {"--frames", chunk}));
        ASSERT_EQ(r.exitCode, 0) << chunk << ": " << r.err;
    }
    for (int f = 1; f <= kFrames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "o.%04d.exr", f);
        EXPECT_EQ(slurp(whole.file(name)), slurp(chunks.file(name))) << name;
    }
    // Each chunk merged its rows into the one coverage.csv.
    EXPECT_EQ(slurp(whole.file("coverage.csv")), slurp(chunks.file("coverage.csv")));
}

TEST(ShotCli, ATrackMovesTheLightAndSequenceFramesEqualSingleImageCalls) {
    TempDir in, out;
    writeShot(in, 4);
    std::ofstream(in.file("track.csv")) << "frame,x,y,intensity\n1,20,20,1\n3,60,40,2\n";
    CliResult r = runCli({"apply", in.file("in.%04d.exr"), "-o", out.file("t.%04d.exr"),
                          "--light-track", in.file("track.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("frames 4 are outside the keys"), std::string::npos) << r.err;
    // Frame 2 is halfway: the light at 40,30 with intensity 1.5, exactly as one call places it
    // at that strength (a track's intensities are absolute, not measured).
    r = runCli({"apply", in.file("in.0002.exr"), "-o", out.file("single.exr"), "--light", "40,30",
                "--intensity", "1.5", "--flux-mode", "fixed"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("t.0002.exr")), slurp(out.file("single.exr")));
    // postfx over the sequence gives what it gives each frame alone.
    r = runCli({"postfx", in.file("in.####.exr"), "-o", out.file("p.####.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"postfx", in.file("in.0003.exr"), "-o", out.file("p3.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("p.0003.exr")), slurp(out.file("p3.exr")));
}

TEST(ShotCli, AMissingFrameStopsBeforeAnyWorkOrIsSkippedAndNamed) {
    TempDir in, out;
    writeShot(in, 8);
    fs::remove(in.file("in.0005.exr"));
    CliResult r =
        runCli({"postfx", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--frames", "1-8"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("frame 5 is missing"), std::string::npos) << r.err;
    EXPECT_EQ(filesIn(out.path()), 0u);
    r = runCli({"postfx", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--frames", "1-9",
                "--skip-missing"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("skipping missing frames 5, 9"), std::string::npos) << r.err;
    EXPECT_EQ(filesIn(out.path()), 7u);
}

TEST(ShotCli, AFrameOfAnotherSizeFailsNamingItAndTheFinishedFramesStayComplete) {
    TempDir in, out;
    writeShot(in, 10, 6);
    const CliResult r = runCli(shotArgs(in, out.file("o.####.exr")));
    EXPECT_EQ(r.exitCode, 2);
    // One error line (the progress lines before it are not errors).
    EXPECT_NE(r.err.find("flarekit: frame 6: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("written and complete"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("flarekit:", r.err.find("flarekit: frame 6") + 1), std::string::npos);
    EXPECT_FALSE(fs::exists(out.file("o.0006.exr")));
    for (const auto& e : fs::directory_iterator(out.path())) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(name.rfind("o.", 0), 0u) << "left behind: " << name;
        EXPECT_TRUE(readImage(e.path().string())) << name << " is not a complete image";
    }
    EXPECT_FALSE(fs::exists(out.file("coverage.csv")));
}

TEST(ShotCli, EveryBadShotInputIsOneLineAndWritesNothing) {
    TempDir in, out;
    writeShot(in, 3);
    std::ofstream(in.file("unsorted.csv")) << "frame,x,y\n3,1,1\n1,2,2\n";
    std::ofstream(in.file("nan.csv")) << "frame,x,y\n1,nan,1\n";
    Image small(8, 8);
    ASSERT_TRUE(writeImage(in.file("smallmatte.0001.exr"), small));
    ASSERT_TRUE(writeImage(in.file("smallmatte.0002.exr"), small));
    ASSERT_TRUE(writeImage(in.file("smallmatte.0003.exr"), small));
    const std::string seq = in.file("in.####.exr"), o = out.file("o.####.exr");
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"apply", seq, "-o", o, "--light-track", in.file("unsorted.csv")},
         "line 3: frame 1 does not come after frame 3"},
        {{"apply", seq, "-o", o, "--light-track", in.file("nan.csv")},
         "line 2: x: expected a finite number"},
        {{"apply", seq, "-o", seq}, "would overwrite its input"},
        {{"apply", seq, "-o", out.file("plain.exr")}, "the output must be one too"},
        {{"apply", seq, "-o", o, "--frames", "3-1"}, "--frames: expected A-B[:step]"},
        {{"apply", seq, "-o", o, "--light", "9,9", "--matte", in.file("smallmatte.####.exr")},
         "8x8, but the frame 1 it must match is 160x90"},
        {{"apply", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--light-track",
          in.file("nan.csv")},
         "the input is one image"},
        {{"apply", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--matte",
          in.file("matte.0001.exr")},
         "need the light's position"},
        {{"apply", seq, "-o", o, "--camera", in.file("nan.csv")}, "--camera needs the light"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--light-track", in.file("nan.csv")},
         "give one of them"},
        {{"apply", seq, "-o", o, "--camera", in.file("nan.csv"), "--sun-dir", "0,0,0"},
         "--sun-dir: expected X,Y,Z"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--depth-channel", "R"}, "needs --light-depth"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--depth-channel", "Z", "--light-depth", "3"},
         "no channel 'Z' (it has: R, G, B)"},
        // A plate without alpha has no A to take a matte from (its promoted alpha is all 1).
        {{"apply", std::string(FLAREKIT_SAMPLES) + "/sunset.png", "-o", out.file("x.png"),
          "--light", "10,10", "--matte-channel", "A"},
         "no channel 'A' (it has: R, G, B)"},
        {{"postfx", in.file("nothing.####.exr"), "-o", o}, "no frame of this pattern exists"},
        {{"postfx", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--frames", "1-3"},
         "is one image, not a frame pattern"},
        {{"postfx", seq, "-o", in.file("in.0001.exr") + "/o.####.exr"},
         "in.0001.exr' is not a directory"},
    };
    for (const auto& [args, expected] : cases) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << args.back();
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(filesIn(out.path()), 0u) << r.err;
    }
}

TEST(ShotCli, LensRenderTakesASequenceAndItsFramesEqualOneImageCalls) {
    TempDir in, out;
    writeShot(in, 3);
    CliResult r = runCli({"lens", "render", "asahi-takumar-50", in.file("in.####.exr"), "-o",
                          out.file("l.####.exr"), "--light", "100.5,45.5", "--ghosts", "4",
                          "--layers", out.file("layers")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"lens", "render", "asahi-takumar-50", in.file("in.0002.exr"), "-o",
                out.file("single.exr"), "--light", "100.5,45.5", "--ghosts", "4"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("l.0002.exr")), slurp(out.file("single.exr")));
    EXPECT_TRUE(fs::exists(out.file("layers/ghosts.0003.exr")));
    EXPECT_TRUE(fs::exists(out.file("layers/flare.0001.exr")));
}
