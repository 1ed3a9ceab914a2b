// SPDX-License-Identifier: Apache-2.0
// The job layer against the CLI: a shot run through the library alone (flarekit/job/, linked
// without any of tools/flarekit/) writes the same bytes as `flarekit apply`/`postfx` on the same
// inputs, every frame, layer and CSV; and the events a front end gets (progress in order,
// warnings as lines, cancellation) behave as documented.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>

#include "Cli.h"
#include "ShotFixtures.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PostFxJob.h"
#include "flarekit/ocio/OcioTransform.h"

namespace flarekit::test {
namespace {

namespace fs = std::filesystem;
using shot::kFrames;

//! Every file under `dir`, by its path relative to `dir`.
std::map<std::string, std::string> filesUnder(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
    return files;
}

//! The two folders hold the same files with the same bytes (and at least `atLeast` of them).
void expectSameFiles(const fs::path& cli, const fs::path& library, std::size_t atLeast) {
    const auto a = filesUnder(cli), b = filesUnder(library);
    ASSERT_GE(a.size(), atLeast);
    std::set<std::string> names;
    for (const auto& [name, bytes] : a) names.insert(name);
    for (const auto& [name, bytes] : b) names.insert(name);
    for (const std::string& name : names) {
        ASSERT_TRUE(a.count(name)) << name << " written by the library only";
        ASSERT_TRUE(b.count(name)) << name << " written by the CLI only";
        EXPECT_TRUE(a.at(name) == b.at(name)) << name << " differs";
    }
}

//! A light moving 1.5 px a frame with a rising intensity, keyed every 4th frame.
void writeTrack(const std::string& path) {
    std::ofstream out(path);
    out << "frame,x,y,intensity\n";
    for (int f = 1; f <= kFrames; f += 4)
        out << f << "," << 96.5 + 1.5 * f << "," << 45.5 - 0.5 * f << "," << 0.6 + 0.05 * f << "\n";
}

TEST(JobParity, ApplyShotWithTrackMatteAndLayersMatchesTheCli) {
    TempDir in;
    shot::writeShot(in);
    writeTrack(in.file("track.csv"));
    TempDir cli, lib;
    fs::create_directories(cli.file("out"));
    fs::create_directories(lib.file("out"));
    const CliResult r =
        runCli({"apply", in.file("in.####.exr"), "-o", cli.file("out/o.####.exr"), "--light-track",
                in.file("track.csv"), "--matte", in.file("matte.####.exr"), "--light-radius", "6",
                "--layers", cli.file("out/layers"), "--write-track", cli.file("out/track.csv"),
                "--preset", "tanczos-classic", "--intensity", "1.5"});
    ASSERT_EQ(r.exitCode, 0) << r.err;

    ApplyOptions o;
    o.input = in.file("in.####.exr");
    o.output = lib.file("out/o.####.exr");
    o.lightTrack = in.file("track.csv");
    o.occlusion.matte = in.file("matte.####.exr");
    o.occlusion.lightRadius = 6;
    o.layersDir = lib.file("out/layers");
    o.writeTrack = lib.file("out/track.csv");
    o.intensity = 1.5f;
    std::vector<int> progress;
    std::mutex mutex;
    JobEvents events;
    events.progress = [&](int done, int total) {
        std::lock_guard lock(mutex);
        EXPECT_EQ(total, kFrames);
        progress.push_back(done);
    };
    auto report = runApplyJob(o, events);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->sequence);
    EXPECT_EQ(report->shot.frames, kFrames);
    // One call per frame, `done` rising 1..12.
    ASSERT_EQ(progress.size(), std::size_t(kFrames));
    for (int i = 0; i < kFrames; ++i) EXPECT_EQ(progress[std::size_t(i)], i + 1);
    // 12 frames, 12 x (the preset's passes + flare) layers, coverage.csv, the track.
    expectSameFiles(cli.file("out"), lib.file("out"), 2 * kFrames + 2);
}

TEST(JobParity, ApplyOneImageWithColourSpacesMatchesTheCli) {
    TempDir dir;
    const CliResult r =
        runCli({"apply", kSunset, "-o", dir.file("cli/o.png"), "--light", "300,200",
                "--colorspace-in", "srgb", "--colorspace-out", "acescg", "--depth", "16"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ApplyOptions o;
    o.input = kSunset;
    o.output = dir.file("lib/o.png");
    o.light = Point{300, 200};
    o.depth = SampleFormat::U16;
    auto color = createOcioTransform({"srgb", "acescg", ""});
    ASSERT_TRUE(color) << color.error().message;
    o.color = *color;
    auto report = runApplyJob(o);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_FALSE(report->sequence);
    expectSameFiles(dir.file("cli"), dir.file("lib"), 1);
}

TEST(JobParity, PostFxShotMatchesTheCli) {
    TempDir in;
    shot::writeShot(in, 4);
    TempDir cli, lib;
    const CliResult r =
        runCli({"postfx", in.file("in.####.exr"), "-o", cli.file("o.####.png"), "--preset",
                "killzone2", "--save-layers", cli.file("layers"), "--threshold", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    PostFxJobOptions o;
    o.input = in.file("in.####.exr");
    o.output = lib.file("o.####.png");
    o.preset = "killzone2";
    o.layersDir = lib.file("layers");
    o.threshold = 2.f;
    auto report = runPostFxJob(o);
    ASSERT_TRUE(report) << report.error().message;
    expectSameFiles(cli.path(), lib.path(), 4 + 4 * 6);
}

TEST(JobParity, LensShotWithEverySourceMatchesTheCli) {
    TempDir in;
    shot::writeShot(in, 3);
    TempDir cli, lib;
    const CliResult r = runCli({"lens", "render", "angenieux-double-gauss", in.file("in.####.exr"),
                                "-o", cli.file("o.####.exr"), "--light", "all", "--layers",
                                cli.file("layers"), "--ghosts", "6", "--grid", "24"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    LensJobOptions o;
    o.lens = "angenieux-double-gauss";
    o.input = in.file("in.####.exr");
    o.output = lib.file("o.####.exr");
    o.lightMode = LensLightMode::All;
    o.layersDir = lib.file("layers");
    o.render.ghosts = 6;
    o.render.gridSide = 24;
    std::vector<std::string> said;
    std::mutex mutex;
    JobEvents events;
    events.info = [&](const std::string& line) {
        std::lock_guard lock(mutex);
        said.push_back(line);
    };
    auto report = runLensJob(o, events);
    ASSERT_TRUE(report) << report.error().message;
    expectSameFiles(cli.path(), lib.path(), 3 + 3 * 4);
    // One summary line per frame, as the CLI prints on stdout.
    ASSERT_EQ(said.size(), 3u);
    for (const std::string& line : said)
        EXPECT_NE(r.out.find(line.substr(line.find(':'))), std::string::npos) << line;
}

TEST(JobEvents, BadOptionsAreOneLineErrorsBeforeAnyWork) {
    TempDir in;
    shot::writeShot(in, 2);
    TempDir out;
    ApplyOptions o;
    o.input = in.file("in.####.exr");
    o.output = out.file("o.####.exr");
    o.light = Point{10, 10};
    o.lightTrack = in.file("track.csv");
    auto report = runApplyJob(o);
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(report.error().message, "--light X,Y, --light-track and --camera: give one of them");
    o.lightTrack.clear();
    o.output = out.file("one.exr");
    report = runApplyJob(o);
    ASSERT_FALSE(report);
    EXPECT_NE(report.error().message.find("must be one too"), std::string::npos)
        << report.error().message;
    EXPECT_TRUE(fs::is_empty(out.path()));
}

TEST(JobEvents, WarningsComeAsLinesAndCancelStopsBetweenFrames) {
    TempDir in;
    shot::writeShot(in);
    TempDir out;
    ApplyOptions o;
    o.input = in.file("in.####.exr");
    o.output = out.file("o.####.exr");
    o.light = Point{100.5f, 45.5f};
    o.shot.frames = "1-14";
    o.shot.skipMissing = true;
    std::vector<std::string> warnings;
    std::atomic<int> written{0};
    JobEvents events;
    events.warning = [&](const std::string& line) { warnings.push_back(line); };
    events.progress = [&](int done, int) { written = done; };
    events.cancelled = [&] { return written >= 3; };
    auto report = runApplyJob(o, events);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("skipping missing frames 13-14"), std::string::npos) << warnings[0];
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::Interrupted);
    EXPECT_EQ(report.error().message.rfind("cancelled: ", 0), 0u) << report.error().message;
    // The frames finished before the cancel (3, or 4 with one in flight) are whole files; no
    // frame after them started.
    const std::size_t files = shot::filesIn(out.path());
    EXPECT_GE(files, 3u);
    EXPECT_LE(files, 4u);
    for (const auto& e : fs::directory_iterator(out.path()))
        EXPECT_TRUE(readImage(e.path().string())) << e.path();
}

}  // namespace
}  // namespace flarekit::test
