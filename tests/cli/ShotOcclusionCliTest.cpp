// SPDX-License-Identifier: Apache-2.0
// Occlusion over a shot: coverage.csv against the closed-form share of a disc behind a moving
// edge, frame by frame, the filter against an independent exponential smoother, and the plate's
// own depth and matte channels read by name.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfTimeCodeAttribute.h>
#include <gtest/gtest.h>
#include <half.h>

#include "ShotFixtures.h"

using namespace flarekit;
using namespace flarekit::test;
using namespace flarekit::test::shot;

TEST(ShotCli, CoverageFollowsTheEdgeFrameByFrameAndTheFilterIsAnExponentialSmoother) {
    TempDir in, out;
    writeShot(in);
    const CliResult r = runCli(shotArgs(in, out.file("o.####.exr")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readCoverage(out.file("coverage.csv"));
    ASSERT_EQ(rows.size(), std::size_t(kFrames));
    // Independent filter: attack 0.04 s / release 0.12 s at 24 fps from the first frame on.
    double smoothed = 0;
    for (int f = 1; f <= kFrames; ++f) {
        const Row& row = rows.at(f);
        EXPECT_DOUBLE_EQ(row.x, kLightX);
        EXPECT_DOUBLE_EQ(row.y, kLightY);
        const double expected = 1 - segmentShare(kLightX - edgeAt(f), kRadius);
        EXPECT_NEAR(row.raw, expected, 0.01) << "frame " << f;
        const double tau = row.raw > smoothed ? 0.04 : 0.12;
        smoothed =
            f == 1 ? row.raw : smoothed + (1 - std::exp(-1.0 / 24 / tau)) * (row.raw - smoothed);
        EXPECT_NEAR(row.filtered, smoothed, 1e-3) << "frame " << f;
    }
    // The edge sweeps the disc: visible at first, hidden at the end.
    EXPECT_EQ(rows.at(1).raw, 1.0);
    EXPECT_EQ(rows.at(kFrames).raw, 0.0);
    // The flare dims with it: the light a frame's flare adds over its input is in proportion
    // to the filtered coverage (the sprite flare is linear in its intensity; 0.005: the frames
    // are written as half floats, 2^-11 of each value).
    auto added = [&](int f) {
        char name[32];
        std::snprintf(name, sizeof name, "%04d.exr", f);
        auto flared = readImage(out.file(std::string("o.") + name));
        auto input = readImage(in.file(std::string("in.") + name));
        double sum = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) sum += flared->image.at(x, y).g - input->image.at(x, y).g;
        return sum;
    };
    const double full = added(1);
    EXPECT_GT(full, 10.0);
    for (int f = 2; f <= kFrames; ++f)
        EXPECT_NEAR(added(f) / full, rows.at(f).filtered, 0.005) << "frame " << f;
}

TEST(ShotCli, ThePlatesOwnDepthAndMatteChannelsHideTheLightByName) {
    // Frames whose EXR carries a depth (Z: 5 on the foreground left of the edge, 1000 behind)
    // and a foreground matte (fg.A) beside the colour; the light at depth 100.
    TempDir dir;
    constexpr int frames = 6;
    for (int f = 1; f <= frames; ++f) {
        std::vector<float> rgba(std::size_t(kW * kH * 4), 0.1f), z(std::size_t(kW * kH));
        std::vector<half> fg(std::size_t(kW * kH));
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const std::size_t i = std::size_t(y * kW + x);
                const bool front = x < 88 + 4 * f;
                z[i] = front ? 5.f : 1000.f;
                fg[i] = half(front ? 1.f : 0.f);
            }
        char name[32];
        std::snprintf(name, sizeof name, "in.%04d.exr", f);
        writeExrPlate(dir.file(name), Imf::Header(kW, kH), rgba, "Z", z, "fg.A", fg);
    }
    for (const std::vector<std::string>& how :
         {std::vector<std::string>{"--depth-channel", "Z", "--light-depth", "100"},
          std::vector<std::string>{"--matte-channel", "fg.A"}}) {
        TempDir out;
        const CliResult r =
            runCli(with({"apply", dir.file("in.####.exr"), "-o", out.file("o.####.exr"), "--light",
                         "100.5,45.5", "--light-radius", "6"},
                        how));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto rows = readCoverage(out.file("coverage.csv"));
        ASSERT_EQ(rows.size(), std::size_t(frames));
        for (int f = 1; f <= frames; ++f)
            EXPECT_NEAR(rows.at(f).raw, 1 - segmentShare(kLightX - (88 + 4 * f), kRadius), 0.01)
                << how[0] << " frame " << f;
        // The depth and the matte pass through to the output.
        Imf::InputFile o(out.file("o.0001.exr").c_str());
        EXPECT_NE(o.header().channels().findChannel("Z"), nullptr);
        EXPECT_NE(o.header().channels().findChannel("fg.A"), nullptr);
    }
}
