// SPDX-License-Identifier: Apache-2.0
// What a hostile user hands the CLI. Nothing the user had is lost: every file a job would write
// (the output, each layer, each frame's) is checked against every file it reads and against the
// others, by file identity, before any work; each refusal is one line naming both files, exit
// 2, and every file stays as it was. And nothing broken is flared silently: a JPEG without all
// its data is exit 2, not a grey slab under a flare.
#include <gtest/gtest.h>

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
