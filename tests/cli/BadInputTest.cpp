// SPDX-License-Identifier: Apache-2.0
// Bad input: a one-line error naming the file, exit code 2, and no output left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "Cli.h"
#include "RawFiles.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

// CRC-32 of PNG chunks (ISO 3309 polynomial, as in the PNG specification's sample code).
std::uint32_t crc32(const unsigned char* data, std::size_t n) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= data[i];
        for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

void expectRejected(const CliResult& r, const TempDir& dir, std::size_t entriesBefore,
                    const std::string& mention) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("flarekit: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos)
        << "expected '" << mention << "' in: " << r.err;
    EXPECT_EQ(dir.entries(), entriesBefore) << "no output and no temporary file may be left";
}

}  // namespace

TEST(BadInput, MissingFile) {
    TempDir dir;
    expectRejected(runCli({"apply", dir.file("nope.png"), "-o", dir.file("o.png")}), dir, 0,
                   "nope.png: cannot read");
}

TEST(BadInput, CorruptAndTruncatedPngAndExr) {
    TempDir dir;
    Image img(128, 96);
    img.fill({0.9f, 0.5f, 0.2f, 1.f});
    ASSERT_TRUE(writeImage(dir.file("good.png"), img).ok());
    ASSERT_TRUE(writeImage(dir.file("good.exr"), img).ok());
    truncateFile(dir.file("good.png"), dir.file("cut.png"), 100);
    truncateFile(dir.file("good.exr"), dir.file("cut.exr"), 400);
    {
        std::ofstream junk(dir.file("junk.exr"), std::ios::binary);
        junk << "v/1\x01garbage that is no EXR at all";
    }
    for (const char* name : {"cut.png", "cut.exr", "junk.exr"}) {
        expectRejected(runCli({"apply", dir.file(name), "-o", dir.file("o.png")}), dir, 5, name);
    }
}

TEST(BadInput, TooLargeAndEmptyImages) {
    TempDir dir;
    ASSERT_TRUE(
        writeRawBytes(dir.file("wide.png"), 32769, 1, 1, std::vector<unsigned char>(32769, 200)));
    expectRejected(runCli({"apply", dir.file("wide.png"), "-o", dir.file("o.png")}), dir, 1,
                   "image size 32769x1: expected width and height in [1, 32768]");
    // A PNG whose header says 0x0: valid signature, IHDR with a correct CRC, zero dimensions.
    std::vector<unsigned char> zero = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0,
                                       0,    13,  'I', 'H', 'D',  'R',  0,    0,    0, 0,
                                       0,    0,   0,   0,   8,    2,    0,    0,    0};
    const std::uint32_t crc = crc32(zero.data() + 12, 17);
    for (int shift : {24, 16, 8, 0}) zero.push_back(static_cast<unsigned char>(crc >> shift));
    std::ofstream(dir.file("zero.png"), std::ios::binary)
        .write(reinterpret_cast<const char*>(zero.data()), std::streamsize(zero.size()));
    expectRejected(runCli({"apply", dir.file("zero.png"), "-o", dir.file("o.png")}), dir, 2,
                   "zero.png");
}

TEST(BadInput, NanAndInfPixelsAreSanitisedWithAWarning) {
    TempDir dir;
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    std::vector<float> px(64 * 64 * 3, 0.05f);
    px[0] = nan;
    // A light (4,000 x the frame's median) whose red overflowed: read as 65504, not as a hole.
    px[3 * (32 * 64 + 40)] = inf;
    px[3 * (32 * 64 + 40) + 1] = px[3 * (32 * 64 + 40) + 2] = 200.f;
    ASSERT_TRUE(writeRawFloat(dir.file("nan.exr"), 64, 64, 3, px));
    const CliResult r = runCli({"apply", dir.file("nan.exr"), "-o", dir.file("o.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("2 NaN/Inf values: NaN read as 0, infinities clamped to +-65504"),
              std::string::npos)
        << r.err;
    auto out = readImage(dir.file("o.exr"));
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(out->nonFinite, 0u);
    EXPECT_GT(out->image.at(43, 32).r, 0.05f + 1e-3f);  // its flare lights the pixels around it
}

TEST(BadInput, InvalidPresetNamesFileAndField) {
    TempDir dir;
    std::ofstream(dir.file("p.json"))
        << R"({"elements":[{"type":"glow"},{"type":"ring"},{"type":"disc"},{"type":"disc","size":"big"}]})";
    expectRejected(
        runCli({"apply", kSunset, "-o", dir.file("o.png"), "--preset", dir.file("p.json")}), dir, 1,
        dir.file("p.json") + R"(: element[3].size: expected a number in [0, 4], got "big")");
    expectRejected(runCli({"elements", "--preset", dir.file("p.json"), "-o", dir.file("o.png")}),
                   dir, 1, "element[3].size");
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("o.png"), "--preset", "no-such"}), dir,
                   1, "preset 'no-such': expected a JSON file or one of:");
}

TEST(BadInput, AMissingOutputFolderIsMadeAndAFileInItsWayIsRefused) {
    TempDir dir;
    // Every output makes its missing folders, as --layers does: -o out/x.png in an empty folder.
    CliResult r = runCli({"apply", kSunset, "-o", dir.file("new/deeper/o.png")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("new/deeper/o.png")));
    r = runCli({"elements", "-o", dir.file("other/s.png")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("other/s.png")));
    std::filesystem::remove_all(dir.file("new"));
    std::filesystem::remove_all(dir.file("other"));
    // A file where a folder must go: one line, nothing made.
    std::ofstream(dir.file("plain")) << "x";
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("plain/sub/o.png")}), dir, 1,
                   "cannot be made: '" + dir.file("plain") + "' is not a directory");
    expectRejected(runCli({"elements", "-o", dir.file("plain/s.png")}), dir, 1,
                   "is not a directory");
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("o.unknownext")}), dir, 1,
                   "unsupported output format");
}

TEST(BadInput, BadLightAndIntensity) {
    TempDir dir;
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("o.png"), "--light", "10;20"}), dir, 0,
                   "--light: expected X,Y in pixels or 'auto', got '10;20'");
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("o.png"), "--light", "nan,3"}), dir, 0,
                   "--light");
    expectRejected(runCli({"apply", kSunset, "-o", dir.file("o.png"), "--intensity", "-1"}), dir, 0,
                   "--intensity");
}

TEST(BadInput, BlendRejectsNon8BitInput) {
    TempDir dir;
    std::vector<float> px(4 * 4 * 4, 0.5f);
    ASSERT_TRUE(writeRawFloat(dir.file("f.exr"), 4, 4, 4, px));
    ASSERT_TRUE(writeRawBytes(dir.file("d.png"), 4, 4, 3, std::vector<unsigned char>(48, 9)));
    expectRejected(runCli({"blend", "--mode", "add", "--src", dir.file("f.exr"), "--dst",
                           dir.file("d.png"), "-o", dir.file("o.png")}),
                   dir, 2, "expected an 8-bit image");
}

// A hand-placed light is measured as the finder measures it: placed on the found sun it draws
// exactly the found sun's flare; --flux-mode fixed draws the preset's own strength instead; a
// placed light on black draws nothing; an unknown mode is one line, exit 2, nothing written.
TEST(PlacedLight, IsMeasuredLikeAFoundOneUnlessTheFluxIsFixed) {
    TempDir dir;
    std::vector<float> px(96 * 64 * 3, 0.05f);
    for (int y = 30; y < 34; ++y)
        for (int x = 60; x < 64; ++x)
            for (int c = 0; c < 3; ++c) px[std::size_t(3 * (y * 96 + x) + c)] = 400.f;
    ASSERT_TRUE(writeRawFloat(dir.file("sun.exr"), 96, 64, 3, px));
    const std::string in = dir.file("sun.exr");
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("auto.exr")}).exitCode, 0);
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("placed.exr"), "--light", "62,32"}).exitCode, 0);
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("fixed.exr"), "--light", "62,32", "--flux-mode",
                      "fixed"})
                  .exitCode,
              0);
    EXPECT_EQ(slurp(dir.file("auto.exr")), slurp(dir.file("placed.exr")));
    auto placed = readImage(dir.file("placed.exr")), fixed = readImage(dir.file("fixed.exr"));
    ASSERT_TRUE(placed.ok() && fixed.ok());
    // 16 px of 400 in a 64 px tall frame: flare scale 6400 / 64^2 = 1.56, stronger than fixed.
    EXPECT_GT(placed->image.at(70, 32).r, fixed->image.at(70, 32).r);
    // On the dim sky far from the sun: the sky's own small flux, a flare under 1% of the fixed
    // one placed there.
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("dim.exr"), "--light", "8,8"}).exitCode, 0);
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("dimfixed.exr"), "--light", "8,8", "--flux-mode",
                      "fixed"})
                  .exitCode,
              0);
    auto dim = readImage(dir.file("dim.exr")), dimFixed = readImage(dir.file("dimfixed.exr"));
    ASSERT_TRUE(dim.ok() && dimFixed.ok());
    const float added = dim->image.at(8, 8).r - 0.05f,
                addedFixed = dimFixed->image.at(8, 8).r - 0.05f;
    EXPECT_GT(addedFixed, 0.1f);
    EXPECT_LT(added, 0.01f * addedFixed);
    const CliResult bad =
        runCli({"apply", in, "-o", dir.file("bad.exr"), "--light", "8,8", "--flux-mode", "loud"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(lineCount(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find("--flux-mode"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.exr")));
}
