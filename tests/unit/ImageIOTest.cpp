// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "RawFiles.h"
#include "TempDir.h"
#include "TestImages.h"
#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using flarekit::test::TempDir;

TEST(ImageIO, PngRoundTripIsExactInCodeValues) {
    TempDir dir;
    Image img(37, 11);
    for (int y = 0; y < 11; ++y) {
        for (int x = 0; x < 37; ++x) {
            img.at(x, y) = {srgb8ToLinear(std::uint8_t(x * 7)), srgb8ToLinear(std::uint8_t(y * 23)),
                            srgb8ToLinear(std::uint8_t(x + y)), 1.f};
        }
    }
    ASSERT_TRUE(writeImage(dir.file("a.png"), img).ok());
    auto back = readImage(dir.file("a.png"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_FALSE(back->wasFloat);
    EXPECT_FALSE(back->hasAlpha);
    for (int y = 0; y < 11; ++y) {
        for (int x = 0; x < 37; ++x) {
            ASSERT_EQ(linearToSrgb8(back->image.at(x, y).r), x * 7);
            ASSERT_EQ(linearToSrgb8(back->image.at(x, y).g), y * 23);
        }
    }
    auto raw = readImage8(dir.file("a.png"));
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(raw->channels, 3);
    EXPECT_EQ(raw->pixels[3 * 5], 35);  // x = 5 red code, no colour conversion
}

TEST(ImageIO, ExrKeepsLinearHdrValues) {
    TempDir dir;
    Image img(4, 3);
    img.fill({50.f, 0.001f, 2.5f, 0.5f});
    ASSERT_TRUE(
        writeImage(dir.file("a.exr"), img, {SampleFormat::Float, true, true, nullptr, {}, {}})
            .ok());
    auto back = readImage(dir.file("a.exr"));
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(back->wasFloat);
    EXPECT_TRUE(back->hasAlpha);
    EXPECT_FLOAT_EQ(back->image.at(2, 1).r, 50.f);
    EXPECT_FLOAT_EQ(back->image.at(2, 1).g, 0.001f);
    EXPECT_FLOAT_EQ(back->image.at(2, 1).a, 0.5f);
}

// NaN reads as 0; an infinity (a half file's overflow: a light brighter than the format holds)
// as the largest finite half, so a clipped sun stays the brightest thing in the frame.
TEST(ImageIO, NonFiniteValuesAreReplacedAndCounted) {
    TempDir dir;
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    ASSERT_TRUE(test::writeRawFloat(dir.file("bad.exr"), 2, 1, 3, {nan, 1.f, 2.f, inf, -inf, 3.f}));
    auto r = readImage(dir.file("bad.exr"));
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->nonFinite, 3u);
    EXPECT_EQ(r->image.at(0, 0).r, 0.f);
    EXPECT_EQ(r->image.at(0, 0).g, 1.f);
    EXPECT_EQ(r->image.at(1, 0).r, 65504.f);
    EXPECT_EQ(r->image.at(1, 0).g, -65504.f);
    EXPECT_EQ(r->image.at(1, 0).b, 3.f);
}

TEST(ImageIO, AnExrsChannelsPastRgbaAreKeptForTheWriteOthersAreCounted) {
    TempDir dir;
    ASSERT_TRUE(test::writeRawFloat(dir.file("five.exr"), 1, 1, 5, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f}));
    auto r = readImage(dir.file("five.exr"));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->fileChannels, 5);
    EXPECT_EQ(r->droppedChannels, 0);
    EXPECT_EQ(r->extraChannels, 1);
    ASSERT_TRUE(r->exrExtras);
    ASSERT_TRUE(test::writeRawFloat(dir.file("five.tif"), 1, 1, 5, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f}));
    auto t = readImage(dir.file("five.tif"));
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t->droppedChannels, 1);
    EXPECT_FALSE(t->exrExtras);
}

TEST(ImageIO, OversizedImagesAreRejectedBeforeAllocating) {
    TempDir dir;
    ASSERT_TRUE(test::writeRawBytes(dir.file("wide.png"), kMaxImageSide + 1, 1, 1,
                                    std::vector<unsigned char>(std::size_t(kMaxImageSide) + 1, 9)));
    auto r = readImage(dir.file("wide.png"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(
        r.error().message,
        dir.file("wide.png") + ": image size 32769x1: expected width and height in [1, 32768]");
}

TEST(ImageIO, TruncatedFilesAreErrors) {
    TempDir dir;
    Image img(64, 64);
    img.fill({0.5f, 0.25f, 1.f, 1.f});
    for (const char* name : {"t.png", "t.exr"}) {
        ASSERT_TRUE(writeImage(dir.file(name), img).ok());
        test::truncateFile(dir.file(name), dir.file(std::string("cut-") + name), 60);
        auto r = readImage(dir.file(std::string("cut-") + name));
        ASSERT_FALSE(r.ok()) << name;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    }
}

// libjpeg fills the rows a truncated stream never delivered with grey and only warns: flarekit
// refuses such a file as a truncated PNG or TIFF is refused, never returns the grey slab. Cut
// mid-scan, cut just before the end marker, and a header claiming 4000x4000 over its few KB.
TEST(ImageIO, AJpegWithoutAllItsDataIsAnError) {
    TempDir dir;
    const Image img = test::imageOf(160, 120, 5, [](int, int, auto unit) {
        return Rgba{unit(), unit(), 0.5f, 1.f};
    });
    ASSERT_TRUE(writeImage(dir.file("j.jpg"), img).ok());
    const std::string bytes = test::readFile(dir.file("j.jpg"));
    test::truncateFile(dir.file("j.jpg"), dir.file("half.jpg"), bytes.size() / 2);
    test::truncateFile(dir.file("j.jpg"), dir.file("no-eoi.jpg"), bytes.size() - 2);
    // The frame header (SOF0: FF C0, length, precision, then height and width, big-endian).
    std::string big = bytes;
    const std::size_t sof = big.find("\xFF\xC0");
    ASSERT_NE(sof, std::string::npos);
    for (std::size_t at : {sof + 5, sof + 7})
        big[at] = char(4000 >> 8), big[at + 1] = char(4000 & 255);
    test::writeFile(dir.file("big.jpg"), big);
    for (const char* name : {"half.jpg", "big.jpg"}) {
        auto r = readImage(dir.file(name));
        ASSERT_FALSE(r.ok()) << name << " read as a " << r->image.width() << "x"
                             << r->image.height() << " image";
        EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
        EXPECT_NE(r.error().message.find("remature end of"), std::string::npos)
            << r.error().message;
    }
    // Every row is there and only the end marker is missing: the image is whole, one warning.
    auto whole = readImage(dir.file("no-eoi.jpg"));
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    EXPECT_NE(whole->decoderWarning.find("Premature end of JPEG file"), std::string::npos);
    auto clean = readImage(dir.file("j.jpg"));
    ASSERT_TRUE(clean.ok());
    EXPECT_EQ(clean->decoderWarning, "");
}

// Cut inside the pixel data, after libpng has handed over many bands that the reader converts
// while decoding: an error, and no band converted from freed memory (the sanitizer build).
TEST(ImageIO, APngCutMidImageIsAnError) {
    TempDir dir;
    const Image img = test::imageOf(300, 400, 3, [](int, int, auto unit) {
        return Rgba{unit(), unit(), 0.5f, 1.f};
    });
    ASSERT_TRUE(writeImage(dir.file("n.png"), img).ok());
    const auto size = std::filesystem::file_size(dir.file("n.png"));
    test::truncateFile(dir.file("n.png"), dir.file("cut.png"), std::size_t(size * 6 / 10));
    auto r = readImage(dir.file("cut.png"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(r.error().message.find("cannot decode image"), std::string::npos)
        << r.error().message;
}

// A PNG's bands are converted by a helper task while libpng decodes: on a pool of one thread
// (no helper ever runs beside the reader) the reader converts them itself, to the same image.
TEST(ImageIO, APngReadsTheSameOnOneThread) {
    TempDir dir;
    const Image img = test::imageOf(211, 333, 8, [](int x, int y, auto unit) {
        return Rgba{unit(), float(x % 9) / 9.f, float(y % 5) / 5.f, 1.f};
    });
    ASSERT_TRUE(writeImage(dir.file("t.png"), img).ok());
    auto two = readImage(dir.file("t.png"));
    ASSERT_TRUE(two.ok());
    Result<LoadedImage> one = internalError("not read");
    {
        ThreadLimit limit(1);
        one = readImage(dir.file("t.png"));
    }
    ASSERT_TRUE(one.ok());
    ASSERT_EQ(std::memcmp(one->image.data(), two->image.data(), img.pixelCount() * 16), 0);
    for (int x = 0; x < img.width(); ++x)  // and what was written, through the 8-bit codes
        ASSERT_EQ(linearToSrgb8(one->image.at(x, 300).r), linearToSrgb8(img.at(x, 300).r));
}

// No format holds an image without pixels: every writer refuses one with an error (OpenImageIO's
// BMP writer used to die of a division by zero), and nothing is written.
TEST(ImageIO, AnImageWithoutPixelsIsRefused) {
    TempDir dir;
    for (const char* name : {"e.png", "e.jpg", "e.tif", "e.exr", "e.bmp", "e.hdr"}) {
        for (const auto& [w, h] : {std::pair{0, 5}, std::pair{5, 0}}) {
            const Status s = writeImage(dir.file(name), Image(w, h));
            ASSERT_FALSE(s.ok()) << name;
            EXPECT_EQ(s.error().code, ErrorCode::InvalidInput);
            EXPECT_EQ(s.error().message, dir.file(name) + ": nothing to write: the image is " +
                                             std::to_string(w) + "x" + std::to_string(h));
            const Status s8 = writeImage8(dir.file(name), Image8{w, h, 3, {}});
            ASSERT_FALSE(s8.ok()) << name;
            EXPECT_FALSE(std::filesystem::exists(dir.file(name))) << name;
        }
    }
}

TEST(ImageIO, GreyAndGreyAlphaArePromoted) {
    TempDir dir;
    Image8 grey{2, 1, 2, {128, 255, 64, 0}};
    ASSERT_TRUE(writeImage8(dir.file("ga.png"), grey).ok());
    auto back = readImage(dir.file("ga.png"));
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(back->hasAlpha);
    EXPECT_FLOAT_EQ(back->image.at(0, 0).r, back->image.at(0, 0).b);
    EXPECT_FLOAT_EQ(back->image.at(0, 0).r, srgb8ToLinear(128));
    EXPECT_FLOAT_EQ(back->image.at(1, 0).a, 0.f);
}

TEST(ImageIO, AtomicWriteLeavesOnlyTheTarget) {
    TempDir dir;
    ASSERT_TRUE(writeImage(dir.file("x.png"), Image(8, 8)).ok());
    EXPECT_EQ(dir.entries(), 1u);
    // A file standing where a folder must be made: refused, nothing left.
    EXPECT_FALSE(writeImage(dir.file("x.png/y.png"), Image(8, 8)).ok());
    EXPECT_FALSE(writeImage(dir.file("x.nosuchformat"), Image(8, 8)).ok());
    EXPECT_EQ(dir.entries(), 1u);
}

TEST(ImageIO, MissingAndGarbageFilesAreErrorsNotCrashes) {
    TempDir dir;
    auto missing = readImage(dir.file("none.png"));
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::Io);
    std::ofstream(dir.file("junk.png")) << "this is not a png";
    auto junk = readImage(dir.file("junk.png"));
    ASSERT_FALSE(junk.ok());
    EXPECT_EQ(junk.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(junk.error().message.find("junk.png"), std::string::npos);
}

// A phone stores a portrait sideways and says so in EXIF Orientation: the image is read the way
// it is meant to be seen. Each of the eight orientations against the pixel it must move.
TEST(ImageIO, ExifOrientationIsApplied) {
    TempDir dir;
    // 3 x 2 stored pixels with distinct grey levels: level = 40 * (1 + x + 3 y).
    std::vector<unsigned char> px(3 * 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            px[std::size_t(y * 3 + x)] = (unsigned char)(40 * (1 + x + 3 * y));
    auto stored = [&](int x, int y) {
        return srgb8ToLinear((unsigned char)(40 * (1 + x + 3 * y)));
    };
    // For each orientation: the displayed size and which stored pixel lands at displayed (0, 0)
    // and (1, 0).
    struct Case {
        int o, w, h, x00, y00, x10, y10;
    };
    for (const Case c :
         {Case{1, 3, 2, 0, 0, 1, 0}, Case{2, 3, 2, 2, 0, 1, 0}, Case{3, 3, 2, 2, 1, 1, 1},
          Case{4, 3, 2, 0, 1, 1, 1}, Case{5, 2, 3, 0, 0, 0, 1}, Case{6, 2, 3, 0, 1, 0, 0},
          Case{7, 2, 3, 2, 1, 2, 0}, Case{8, 2, 3, 2, 0, 2, 1}}) {
        std::string name = "o";  // appended, not concatenated: GCC 12's -Wrestrict false alarm
        name += std::to_string(c.o);
        name += ".tif";
        const std::string path = dir.file(name);
        ASSERT_TRUE(test::writeRaw(path, 3, 2, 1, OIIO::TypeDesc::UINT8, px.data(), c.o));
        auto img = readImage(path);
        ASSERT_TRUE(img.ok()) << img.error().message;
        ASSERT_EQ(img->image.width(), c.w) << c.o;
        ASSERT_EQ(img->image.height(), c.h) << c.o;
        EXPECT_FLOAT_EQ(img->image.at(0, 0).r, stored(c.x00, c.y00)) << "orientation " << c.o;
        EXPECT_FLOAT_EQ(img->image.at(1, 0).r, stored(c.x10, c.y10)) << "orientation " << c.o;
    }
}

// A movie would read as its first frame; flarekit says it reads still images instead.
TEST(ImageIO, AVideoIsRefusedNotReadAsItsFirstFrame) {
    TempDir dir;
    const std::string mp4 = dir.file("clip.mp4");
    std::string make =
        "ffmpeg -loglevel error -y -f lavfi -i testsrc=size=64x48:rate=10 -t 1 "
        "-pix_fmt yuv420p '";
    make += mp4;
    make += "'";
    ASSERT_EQ(std::system(make.c_str()), 0) << "ffmpeg (scripts/install-deps.sh) is needed";
    auto img = readImage(mp4);
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(img.error().message.find("is a video; flarekit reads still images"),
              std::string::npos)
        << img.error().message;
}

// Half or float samples asked of a format that only holds integers are refused, not silently
// written as 8-bit; nothing is left behind.
TEST(ImageIO, FloatSamplesIntoAnIntegerFormatAreRefused) {
    TempDir dir;
    Image img(4, 4);
    WriteOptions half;
    half.format = SampleFormat::Half;
    const Status s = writeImage(dir.file("o.png"), img, half);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(s.error().message.find("o.png: a '.png' file holds 8, 16 samples, not half"),
              std::string::npos)
        << s.error().message;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
    EXPECT_TRUE(writeImage(dir.file("o.TIF"), img, half).ok());  // extensions in any case
}
