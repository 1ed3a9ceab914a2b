// SPDX-License-Identifier: Apache-2.0
// What a hostile user hands the CLI. Nothing the user had is lost: every file a job would write
// (the output, each layer, each frame's) is checked against every file it reads and against the
// others, by file identity, before any work; each refusal is one line naming both files, exit
// 2, and every file stays as it was. Nothing broken is flared silently: a JPEG without all its
// data is exit 2, not a grey slab under a flare. And every job's memory estimate covers what
// it holds with its layers (its measured peak).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "Cli.h"
#include "flarekit/ImageIO.h"

namespace flarekit::test {
namespace {

namespace fs = std::filesystem;

//! A 48x32 HDR plate: a dim sky and a sun of 50.
void writePlate(const std::string& path) {
    Image image(48, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            const bool sun = (x - 20) * (x - 20) + (y - 12) * (y - 12) < 9;
            const float v = sun ? 50.f : 0.05f + 0.001f * float(x);
            image.at(x, y) = {v, v, v, 1.f};
        }
    ASSERT_TRUE(writeImage(path, image));
}

//! Every file under `dir` and its bytes: what a refused job must leave as it was.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() || e.is_symlink())
            files[fs::relative(e.path(), dir).string()] = slurp(e.path().string());
    return files;
}

//! The job is refused before any work: exit 2, one line naming both files, nothing changed.
void expectRefused(const TempDir& dir, const std::vector<std::string>& args,
                   const std::string& written, const std::string& read) {
    const auto before = snapshot(dir.path());
    const CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(written), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(read), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the same file"), std::string::npos) << r.err;
    EXPECT_EQ(snapshot(dir.path()), before) << "a refused job changed the folder";
}

TEST(FileSafety, APostFxLayerNamedLikeThePlateIsRefused) {
    TempDir dir;
    writePlate(dir.file("final.exr"));
    expectRefused(dir,
                  {"postfx", dir.file("final.exr"), "-o", dir.file("graded.exr"), "--save-layers",
                   dir.path().string()},
                  "layer final of --save-layers", dir.file("final.exr"));
}

TEST(FileSafety, AnApplyLayerNamedLikeThePlateIsRefused) {
    TempDir dir;
    writePlate(dir.file("flare.exr"));
    expectRefused(
        dir, {"apply", dir.file("flare.exr"), "-o", dir.file("out.exr"), "--layers", dir.path()},
        "layer flare of --layers", "the input");
}

TEST(FileSafety, ALensLayerNamedLikeThePlateIsRefused) {
    TempDir dir;
    writePlate(dir.file("glare.exr"));
    expectRefused(dir,
                  {"lens", "render", "angenieux-double-gauss", dir.file("glare.exr"), "-o",
                   dir.file("out.exr"), "--layers", dir.path()},
                  "layer glare of --layers", "the input");
}

TEST(FileSafety, TheOutputOverOneOfItsOwnLayersIsRefused) {
    TempDir dir;
    writePlate(dir.file("plate.exr"));
    expectRefused(
        dir, {"apply", dir.file("plate.exr"), "-o", dir.file("flare.exr"), "--layers", dir.path()},
        "layer flare of --layers", "the output " + dir.file("flare.exr"));
}

TEST(FileSafety, TheOutputOverItsInputIsRefused) {
    TempDir dir;
    writePlate(dir.file("plate.exr"));
    expectRefused(dir, {"postfx", dir.file("plate.exr"), "-o", dir.file("plate.exr")}, "the output",
                  "the input");
}

TEST(FileSafety, AHardLinkToThePlateIsTheSameFile) {
    TempDir dir;
    writePlate(dir.file("plate.exr"));
    fs::create_directory(dir.file("layers"));
    fs::create_hard_link(dir.file("plate.exr"), dir.file("layers/bloom.exr"));
    expectRefused(dir,
                  {"postfx", dir.file("plate.exr"), "-o", dir.file("out.exr"), "--save-layers",
                   dir.file("layers")},
                  "layer bloom of --save-layers", dir.file("plate.exr"));
}

TEST(FileSafety, AFolderReachedThroughALinkIsTheSameFolder) {
    TempDir dir;
    fs::create_directory(dir.file("plates"));
    writePlate(dir.file("plates/sun.exr"));
    fs::create_directory_symlink("plates", dir.file("link"));
    expectRefused(dir, {"apply", dir.file("plates/sun.exr"), "-o", dir.file("link/sun.exr")},
                  "the output", "the input");
    // `..` is resolved the same way.
    expectRefused(dir,
                  {"apply", dir.file("plates/sun.exr"), "-o", dir.file("link/../plates/./sun.exr")},
                  "the output", "the input");
}

TEST(FileSafety, ASequenceWhoseLayersAreItsFramesIsRefused) {
    TempDir dir;
    for (const char* f : {"flare.0001.exr", "flare.0002.exr"}) writePlate(dir.file(f));
    expectRefused(dir,
                  {"apply", dir.file("flare.####.exr"), "-o", dir.file("out/o.####.exr"),
                   "--layers", dir.path()},
                  "layer flare of --layers", dir.file("flare.0001.exr"));
    // postfx writes a frame's layers as DIR/FRAME/NAME.exr: one hard-linked to a frame.
    fs::create_directories(dir.file("seq"));
    fs::create_directories(dir.file("layers/1"));
    writePlate(dir.file("seq/x.0001.exr"));
    fs::create_hard_link(dir.file("seq/x.0001.exr"), dir.file("layers/1/ghosts.exr"));
    expectRefused(dir,
                  {"postfx", dir.file("seq/x.####.exr"), "-o", dir.file("out/p.####.exr"),
                   "--save-layers", dir.file("layers")},
                  "layer ghosts of --save-layers", dir.file("seq/x.0001.exr"));
}

TEST(FileSafety, ALayersFolderBesideThePlateStillWorks) {
    // The check is by identity, not by folder: layers beside a plate named otherwise are fine.
    TempDir dir;
    writePlate(dir.file("plate.exr"));
    const CliResult r = runCli({"apply", dir.file("plate.exr"), "-o", dir.file("out.exr"),
                                "--layers", dir.path(), "--light", "20,12"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir.file("flare.exr")));
    EXPECT_TRUE(fs::exists(dir.file("out.exr")));
}

// A 4 KB output path: the line is cut in the path, never in the reason after it.
TEST(BrokenInput, ALongPathIsCutNotTheReason) {
    TempDir dir;
    writePlate(dir.file("plate.exr"));
    const std::string out = dir.file(std::string(4000, 'a') + ".png");
    const CliResult r = runCli({"apply", dir.file("plate.exr"), "-o", out});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1);
    EXPECT_LE(r.err.size(), 1000u + std::string("flarekit: \n").size());
    EXPECT_NE(r.err.find("File name too long"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("...aaaa"), std::string::npos) << r.err;
}

//! Runs the CLI with `args` and returns its peak resident memory in bytes (wait4's ru_maxrss),
//! or -1 when it failed.
double peakBytes(const std::vector<std::string>& args) {
    std::vector<char*> argv{const_cast<char*>(FLAREKIT_CLI)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, FLAREKIT_CLI, &quiet, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&quiet);
    if (spawned != 0) return -1;
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return double(usage.ru_maxrss) * 1024.0;
}

//! The job's own estimate: what it says when refused under a 1 MiB budget.
double estimatedBytes(const std::vector<std::string>& args) {
    std::vector<std::string> refused{"--max-memory", "1M"};
    refused.insert(refused.end(), args.begin(), args.end());
    const CliResult r = runCli(refused);
    const std::size_t at = r.err.find("needs an estimated ");
    if (r.exitCode != 2 || at == std::string::npos) return -1;
    char unit = 0;
    double value = 0;
    if (std::sscanf(r.err.c_str() + at, "needs an estimated %lf %ciB", &value, &unit) != 2)
        return -1;
    return value * (unit == 'G' ? 1 << 30 : unit == 'M' ? 1 << 20 : 1 << 10);
}

// Every job's budget counts what it holds: with its layers as files or as channels of the
// output, at three sizes, the measured peak stays under the estimate it checks the budget with.
TEST(MemoryBudget, EveryJobWithLayersPeaksUnderItsEstimate) {
    TempDir dir;
    for (const auto& [w, h] : {std::pair{320, 180}, std::pair{960, 540}, std::pair{1920, 1080}}) {
        const std::string plate = dir.file(std::string("plate").append(std::to_string(w)) + ".exr");
        Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float d = std::hypot(float(x - w / 3), float(y - h / 3));
                const float v = d < float(h) / 60.f ? 20000.f : 0.1f + 0.2f * float(y) / float(h);
                image.at(x, y) = {v, v, v, 1.f};
            }
        WriteOptions f32;
        f32.format = SampleFormat::Float;
        ASSERT_TRUE(writeImage(plate, image, f32));
        const std::vector<std::vector<std::string>> jobs = {
            {"apply", plate, "-o", dir.file("a.exr"), "--layers", dir.file("l")},
            {"apply", plate, "-o", dir.file("a.exr"), "--layers-in-output"},
            {"postfx", plate, "-o", dir.file("p.exr"), "--save-layers", dir.file("l")},
            {"postfx", plate, "-o", dir.file("p.exr"), "--layers-in-output"},
            {"lens", "render", "angenieux-double-gauss", plate, "-o", dir.file("r.exr"), "--layers",
             dir.file("l"), "--grid", "24"},
            {"lens", "render", "angenieux-double-gauss", plate, "-o", dir.file("r.exr"),
             "--layers-in-output", "--grid", "24"},
        };
        for (const auto& job : jobs) {
            // Appended: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
            std::string what = std::to_string(w);
            what.append("x").append(std::to_string(h));
            for (const std::string& a : job) what.append(" ").append(a.substr(0, 20));
            const double estimate = estimatedBytes(job), peak = peakBytes(job);
            ASSERT_GT(estimate, 0) << what;
            ASSERT_GT(peak, 0) << what;
            EXPECT_LE(peak, estimate) << what << ": peak " << peak / (1 << 20) << " MiB, estimate "
                                      << estimate / (1 << 20) << " MiB";
        }
    }
}

TEST(BrokenInput, AJpegCutShortIsOneLineAndNoFile) {
    TempDir dir;
    Image image(96, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 96; ++x) image.at(x, y) = {float(x) / 96.f, float(y) / 64.f, 0.5f, 1.f};
    ASSERT_TRUE(writeImage(dir.file("photo.jpg"), image));
    const std::string bytes = slurp(dir.file("photo.jpg"));
    std::ofstream(dir.file("cut.jpg"), std::ios::binary)
        .write(bytes.data(), std::streamsize(bytes.size() / 2));
    for (const char* command : {"apply", "postfx"}) {
        const CliResult r = runCli({command, dir.file("cut.jpg"), "-o", dir.file("out.png")});
        EXPECT_EQ(r.exitCode, 2) << command << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(dir.file("cut.jpg") + ": cannot decode image: Premature end of JPEG"),
                  std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(dir.file("out.png")));
    }
}

}  // namespace
}  // namespace flarekit::test
