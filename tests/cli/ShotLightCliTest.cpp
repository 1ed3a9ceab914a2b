// SPDX-License-Identifier: Apache-2.0
// The light per frame: --light auto following a moving sun past a 40x glint (its written track
// fed back), and a camera per frame projecting the sun, against an independent pinhole.
#include <gtest/gtest.h>

#include "ShotFixtures.h"

using namespace flarekit;
using namespace flarekit::test;
using namespace flarekit::test::shot;

TEST(ShotCli, LightAutoFollowsTheSunPastAFortyTimesGlintAndWritesItsTrack) {
    TempDir in, out;
    writeMovingSun(in, 16, 9);
    const CliResult r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("o.####.exr"),
                                "--write-track", out.file("track.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto track = readTrack(out.file("track.csv"));
    ASSERT_EQ(track.size(), 16u);
    for (const auto& [f, p] : track) {
        EXPECT_NEAR(p.first, 40.5 + 3 * (f - 1), 1.0) << "frame " << f;
        EXPECT_NEAR(p.second, 40.5, 1.0) << "frame " << f;
    }
    // Fed back as a track, it places the same flares.
    const CliResult again = runCli({"apply", in.file("in.####.exr"), "-o", out.file("t.####.exr"),
                                    "--light-track", out.file("track.csv")});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(slurp(out.file("o.0009.exr")), slurp(out.file("t.0009.exr")));
}

TEST(ShotCli, ACameraProjectsTheSunEachFrameAndNoneBehindIt) {
    TempDir in, out;
    writeShot(in, 4);
    // The camera pans from looking down -z to looking down +x; the sun stands 20 degrees up
    // toward -z, so it crosses the frame and is behind the camera by frame 4.
    std::ofstream(in.file("camera.json")) << R"({"frames": [
        {"frame": 1, "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_y_deg": 50},
        {"frame": 4, "position": [0, 0, 0], "look_at": [3, 0, 1], "fov_y_deg": 50}]})";
    const double sun[3] = {0.2, 0.342, -0.9397};  // as given to --sun-dir
    CliResult r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--camera",
                          in.file("camera.json"), "--sun-dir", "0.2,0.342,-0.9397", "--write-track",
                          out.file("track.csv"), "--guard-band", "0"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto track = readTrack(out.file("track.csv"));
    // An independent pinhole projection of each frame's camera (look_at linear between keys).
    const double n = std::hypot(sun[0], sun[1], sun[2]);
    int seen = 0;
    for (int f = 1; f <= 4; ++f) {
        const double t = (f - 1) / 3.0;
        double fw[3] = {3 * t, 0, -1 + 2 * t};
        const double fl = std::hypot(fw[0], fw[1], fw[2]);
        for (double& c : fw) c /= fl;
        const double right[3] = {-fw[2], 0, fw[0]};  // forward x (0, 1, 0)
        const double up[3] = {0, 1, 0};
        const double d[3] = {sun[0] / n, sun[1] / n, sun[2] / n};
        const double depth = d[0] * fw[0] + d[1] * fw[1] + d[2] * fw[2];
        if (depth <= 0) {
            EXPECT_EQ(track.count(f), 0u) << "frame " << f << ": the sun is behind the camera";
            continue;
        }
        const double focal = (kH / 2.0) / std::tan(25 * M_PI / 180);
        const double x = kW / 2.0 + focal * (d[0] * right[0] + d[2] * right[2]) / depth;
        const double y = kH / 2.0 - focal * (d[0] * up[0] + d[1] * up[1] + d[2] * up[2]) / depth;
        // In front: its row, wherever it projects (off the frame too, with no flare there).
        ASSERT_EQ(track.count(f), 1u) << "frame " << f;
        EXPECT_NEAR(track.at(f).first, x, 0.05 + 1e-5 * std::abs(x)) << "frame " << f;
        EXPECT_NEAR(track.at(f).second, y, 0.05 + 1e-5 * std::abs(y)) << "frame " << f;
        ++seen;
    }
    EXPECT_GE(seen, 2);
    EXPECT_LT(seen, 4);
    // A behind-the-camera frame is the input, unflared.
    auto o4 = readImage(out.file("o.0004.exr")), i4 = readImage(in.file("in.0004.exr"));
    EXPECT_EQ(o4->image.at(80, 45).g, i4->image.at(80, 45).g);
}
