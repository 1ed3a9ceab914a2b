// SPDX-License-Identifier: Apache-2.0
// flarekit's own PNG, JPEG, TIFF and EXR codecs against an independent implementation:
// OpenImageIO (linked by the tests only) writes each layout and reads back what flarekit
// writes. Sample values must agree exactly (JPEG: the same libjpeg-turbo decode).
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <sstream>
#include <vector>

#include "RawFiles.h"
#include "TempDir.h"
#include "TestImages.h"
#include "core/HalfFloat.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using flarekit::test::TempDir;

namespace {

constexpr int kW = 37, kH = 23;  // odd sizes: no row happens to fall on a block edge

std::string fileName(int channels, OIIO::TypeDesc type, int tile, const char* extension) {
    std::ostringstream os;
    os << "c" << channels << "-" << type.c_str() << "-" << tile << extension;
    return os.str();
}

//! OIIO's reader with straight alpha kept (by default it multiplies colour by alpha).
std::unique_ptr<OIIO::ImageInput> openStraight(const std::string& path) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return OIIO::ImageInput::open(path, &config);
}

//! Writes `channels` samples of `type` with OIIO (tiled when tile > 0); returns the values it
//! wrote as floats in [0, 1] (or as written, for float types).
std::vector<float> writeWithOiio(const std::string& path, int channels, OIIO::TypeDesc type,
                                 int tile = 0) {
    std::mt19937 rng(unsigned(channels * 31 + int(type.basetype)));
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    std::vector<float> values(std::size_t(kW * kH * channels));
    for (float& v : values) v = unit(rng);
    if (type == OIIO::TypeDesc::UINT8)
        for (float& v : values) v = std::round(v * 255.f) / 255.f;
    if (type == OIIO::TypeDesc::UINT16)
        for (float& v : values) v = std::round(v * 65535.f) / 65535.f;
    if (type == OIIO::TypeDesc::HALF)
        for (float& v : values) v = float(half(v * 8.f));  // HDR values past 1
    if (type == OIIO::TypeDesc::FLOAT)
        for (float& v : values) v *= 8.f;
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(kW, kH, channels, type);
    if (channels == 2 || channels == 4) {
        spec.alpha_channel = channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (tile) spec.tile_width = spec.tile_height = tile;
    EXPECT_TRUE(out && out->open(path, spec) &&
                out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close())
        << path;
    return values;
}

//! What readImage must return for the samples OIIO wrote: sRGB-decoded colour for integer
//! files, grey promoted, alpha as stored, 1 when absent.
void expectRead(const std::string& path, const std::vector<float>& v, int channels, bool srgb) {
    auto r = readImage(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->image.width(), kW);
    ASSERT_EQ(r->image.height(), kH);
    EXPECT_EQ(r->fileChannels, channels);
    EXPECT_EQ(r->hasAlpha, channels == 2 || channels == 4);
    for (int p = 0; p < kW * kH; ++p) {
        const float* s = v.data() + std::size_t(p * channels);
        const float* d = r->image.data() + std::size_t(p) * 4;
        for (int c = 0; c < 3; ++c) {
            const float stored = channels <= 2 ? s[0] : s[c];
            const float expected = srgb ? srgbToLinear(stored) : stored;
            ASSERT_NEAR(d[c], expected, std::abs(expected) * 1e-6f + 1e-7f) << path << " " << p;
        }
        const float alpha = channels == 2 || channels == 4 ? s[channels - 1] : 1.f;
        ASSERT_NEAR(d[3], alpha, 1e-6f) << path << " " << p;
    }
}

}  // namespace

TEST(Codec, PngLayoutsReadAsOpenImageIoWroteThem) {
    TempDir dir;
    for (int channels : {1, 2, 3, 4}) {
        for (auto type : {OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT16}) {
            const std::string path = dir.file(fileName(channels, type, 0, ".png"));
            expectRead(path, writeWithOiio(path, channels, type), channels, true);
        }
    }
}

// Adam7-interlaced PNGs are decoded whole before any row is converted (their rows are final
// only after the seventh pass); plain ones band by band while libpng decodes. Both read the
// same: an interlaced file written with libpng against the values it was given.
TEST(Codec, InterlacedPngReadsAsWritten) {
    TempDir dir;
    const int w = 41, h = 53;  // several bands of rows, the last one short
    std::vector<unsigned char> rgb(std::size_t(w * h * 3));
    std::mt19937 rng(17);
    for (unsigned char& v : rgb) v = static_cast<unsigned char>(rng() & 0xFF);
    const std::string path = dir.file("adam7.png");
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_bytep> rows(static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) rows[std::size_t(y)] = rgb.data() + std::size_t(y * w * 3);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    auto r = readImage(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(
                    r->image.data()[(std::size_t(y) * w + std::size_t(x)) * 4 + std::size_t(c)],
                    srgb8ToLinear(rgb[std::size_t((y * w + x) * 3 + c)]))
                    << x << "," << y;
}

TEST(Codec, TiffLayoutsReadAsOpenImageIoWroteThem) {
    TempDir dir;
    for (int channels : {1, 3, 4}) {
        for (auto type : {OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT16, OIIO::TypeDesc::FLOAT}) {
            for (int tile : {0, 16}) {
                const std::string path = dir.file(fileName(channels, type, tile, ".tif"));
                expectRead(path, writeWithOiio(path, channels, type, tile), channels,
                           type != OIIO::TypeDesc::FLOAT);
            }
        }
    }
}

TEST(Codec, ExrLayoutsReadStraightIntoRgba) {
    TempDir dir;
    for (int channels : {3, 4}) {
        for (auto type : {OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT}) {
            for (int tile : {0, 16}) {
                const std::string path = dir.file(fileName(channels, type, tile, ".exr"));
                expectRead(path, writeWithOiio(path, channels, type, tile), channels, false);
            }
        }
    }
    // A luminance-only file (channel Y): grey promoted, as OIIO reads it.
    const std::string grey = dir.file("y.exr");
    expectRead(grey, writeWithOiio(grey, 1, OIIO::TypeDesc::HALF), 1, false);
}

// Half-float scanline files are read band by band (whole chunks of the file's compression at a
// time, converted by F16C where the CPU has it). Against OpenImageIO's own decode of the same
// file to floats: every compression (so every chunk height, 1 to 256 rows), Y, YA, RGB and RGBA,
// a data window off the origin and a height that leaves a short last band; NaN read as 0 and
// infinities as +-65504 (the largest half), both counted, alpha 1 where the file has none, grey
// copied to G and B.
TEST(Codec, HalfExrBandsReadAsOpenImageIoDecodesThem) {
    TempDir dir;
    const int w = 29, h = 300;
    for (const char* compression :
         {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"}) {
        for (int channels : {1, 2, 3, 4}) {
            std::mt19937 rng(unsigned(channels * 7 + int(std::strlen(compression))));
            std::uniform_real_distribution<float> value(-0.5f, 40.f);
            std::vector<float> written(std::size_t(w * h * channels));
            for (float& v : written) v = value(rng);
            for (std::size_t i = 5; i < written.size(); i += 997)  // NaN, +inf, -inf scattered
                written[i] = i % 3 == 0 ? std::nanf("") : i % 3 == 1 ? INFINITY : -INFINITY;
            const std::string path =
                dir.file(std::string(compression) + std::to_string(channels) + ".exr");
            OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::HALF);
            spec.x = 5, spec.y = -7;  // the data window off the origin
            spec.full_x = 0, spec.full_y = -7, spec.full_width = w + 5, spec.full_height = h;
            if (channels <= 2) {
                spec.channelnames = {"Y", "A"};
                spec.channelnames.resize(std::size_t(channels));
            }
            if (channels == 2 || channels == 4) spec.alpha_channel = channels - 1;
            spec.attribute("oiio:UnassociatedAlpha", 1);
            spec.attribute("compression", compression);
            auto out = OIIO::ImageOutput::create(path);
            ASSERT_TRUE(out && out->open(path, spec) &&
                        out->write_image(OIIO::TypeDesc::FLOAT, written.data()) && out->close())
                << path;
            auto in = openStraight(path);
            ASSERT_TRUE(in) << path;
            std::vector<float> decoded(written.size());
            ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, decoded.data()));
            auto r = readImage(path);
            ASSERT_TRUE(r.ok()) << path << ": " << r.error().message;
            ASSERT_EQ(r->image.width(), w);
            ASSERT_EQ(r->image.height(), h);
            std::size_t nonFinite = 0, mismatches = 0;
            for (std::size_t p = 0; p < std::size_t(w * h); ++p) {
                const float* s = decoded.data() + p * std::size_t(channels);
                const float* d = r->image.data() + p * 4;
                for (int c = 0; c < 4; ++c) {
                    float expected = channels <= 2 ? s[0] : s[std::min(c, 2)];
                    if (c == 3) expected = channels == 2 || channels == 4 ? s[channels - 1] : 1.f;
                    if (!std::isfinite(expected))
                        ++nonFinite, expected = std::isnan(expected) ? 0.f
                                                : expected > 0       ? 65504.f
                                                                     : -65504.f;
                    mismatches += std::memcmp(&expected, &d[c], sizeof expected) != 0;
                }
            }
            EXPECT_EQ(mismatches, 0u) << path;
            EXPECT_EQ(r->nonFinite, nonFinite) << path;
            EXPECT_TRUE(r->halfExact) << path;
        }
    }
}

TEST(Codec, JpegDecodesAsOpenImageIoDecodesIt) {
    TempDir dir;
    for (int channels : {1, 3}) {
        const std::string path = dir.file(fileName(channels, OIIO::TypeDesc::UINT8, 0, ".jpg"));
        writeWithOiio(path, channels, OIIO::TypeDesc::UINT8);
        auto in = OIIO::ImageInput::open(path);
        ASSERT_TRUE(in);
        std::vector<float> decoded(std::size_t(kW * kH * channels));
        ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, decoded.data()));
        expectRead(path, decoded, channels, true);
    }
}

TEST(Codec, WritesReadBackExactlyThroughOpenImageIo) {
    TempDir dir;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(-0.1f, 1.2f);
    Image image(kW, kH);
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) image.data()[i] = value(rng);
    struct Case {
        const char* name;
        SampleFormat format;
        bool alpha;
    };
    for (const Case& c :
         {Case{"a.png", SampleFormat::U8, true}, Case{"b.png", SampleFormat::U16, false},
          Case{"c.tif", SampleFormat::U16, true}, Case{"d.tif", SampleFormat::Float, false},
          Case{"e.exr", SampleFormat::Half, true}, Case{"f.exr", SampleFormat::Float, false},
          Case{"g.bmp", SampleFormat::U8, false}}) {
        const std::string path = dir.file(c.name);
        ASSERT_TRUE(writeImage(path, image, {c.format, c.alpha, true, nullptr, {}, {}}).ok())
            << c.name;
        auto in = openStraight(path);
        ASSERT_TRUE(in) << c.name;
        const int channels = c.alpha ? 4 : 3;
        ASSERT_EQ(in->spec().nchannels, channels) << c.name;
        std::vector<float> back(image.pixelCount() * std::size_t(channels));
        ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, back.data()));
        for (std::size_t p = 0; p < image.pixelCount(); ++p) {
            for (int ch = 0; ch < channels; ++ch) {
                const float v = image.data()[p * 4 + std::size_t(ch)];
                float expected = v;
                if (c.format == SampleFormat::U8)
                    expected = (ch < 3 ? linearToSrgb8(v) : alphaTo8(v)) / 255.f;
                if (c.format == SampleFormat::U16)
                    expected = (ch < 3 ? linearToSrgb16(v) : alphaTo16(v)) / 65535.f;
                if (c.format == SampleFormat::Half) expected = float(half(v));
                ASSERT_FLOAT_EQ(back[p * std::size_t(channels) + std::size_t(ch)], expected)
                    << c.name << " " << p << " " << ch;
            }
        }
    }
}

// Levels 0-3 deflate bands of 128 rows in parallel into one zlib stream (the Sub filter, IDAT
// chunks written whole); higher levels go through libpng's own filtering. Every layout, at
// heights on and around a band edge, decodes through OpenImageIO's reader (libpng, which
// checks the stream's adler32 and every chunk's CRC) to exactly the codes written.
TEST(Codec, PngBandsMakeOneValidStreamAtEveryLevel) {
    TempDir dir;
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> value(0.f, 1.f);
    for (const int height : {1, 128, 129, 300}) {
        Image image(29, height);
        for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) image.data()[i] = value(rng);
        for (int y = 0; y < height; y += 3)  // flat runs too, which deflate finds matches in
            for (int x = 0; x < 29; ++x) image.at(x, y) = image.at(0, y);
        for (const int level : {0, 1, 2, 3, 4, 9}) {
            for (const SampleFormat format : {SampleFormat::U8, SampleFormat::U16}) {
                for (const bool alpha : {false, true}) {
                    const std::string path = dir.file(std::string("b") + std::to_string(height) +
                                                      "-" + std::to_string(level) + ".png");
                    ASSERT_TRUE(
                        writeImage(path, image, {format, alpha, true, nullptr, {}, {level, "", 1}})
                            .ok());
                    auto in = openStraight(path);
                    ASSERT_TRUE(in) << path;
                    const int channels = alpha ? 4 : 3;
                    std::vector<std::uint16_t> back(image.pixelCount() * std::size_t(channels));
                    ASSERT_TRUE(
                        in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT16, back.data()))
                        << path << ": " << in->geterror();
                    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
                        for (int ch = 0; ch < channels; ++ch) {
                            const float v = image.data()[p * 4 + std::size_t(ch)];
                            // OpenImageIO widens 8-bit codes to 16 bits as code x 257.
                            const int expected =
                                format == SampleFormat::U8
                                    ? int(ch < 3 ? linearToSrgb8(v) : alphaTo8(v)) * 257
                                    : int(ch < 3 ? linearToSrgb16(v) : alphaTo16(v));
                            ASSERT_EQ(int(back[p * std::size_t(channels) + std::size_t(ch)]),
                                      expected)
                                << path << " " << int(format) << alpha << " " << p;
                        }
                    }
                    // flarekit's own reader, whose decoded bands go round a ring of 8 (128 rows):
                    // the codes OpenImageIO read, decoded to linear light.
                    auto mine = readImage(path);
                    ASSERT_TRUE(mine.ok()) << mine.error().message;
                    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
                        for (int ch = 0; ch < channels; ++ch) {
                            const std::uint16_t code =
                                back[p * std::size_t(channels) + std::size_t(ch)];
                            const float expected =
                                format == SampleFormat::U8
                                    ? (ch < 3 ? srgb8ToLinear(std::uint8_t(code / 257))
                                              : float(code / 257) * (1.f / 255.f))
                                    : (ch < 3 ? srgb16ToLinear(code)
                                              : float(code) * (1.f / 65535.f));
                            ASSERT_EQ(mine->image.data()[p * 4 + std::size_t(ch)], expected)
                                << path << " " << int(format) << alpha << " " << p;
                        }
                    }
                }
            }
        }
    }
    // Grey and grey + alpha, 8-bit as given (writeImage8: the rows are all made beforehand).
    for (const int channels : {1, 2}) {
        Image8 grey{40, 200, channels, {}};
        grey.pixels.resize(std::size_t(40 * 200 * channels));
        for (unsigned char& v : grey.pixels) v = static_cast<unsigned char>(rng() & 0xFF);
        const std::string path = dir.file(std::string("g") + std::to_string(channels) + ".png");
        ASSERT_TRUE(writeImage8(path, grey).ok());
        auto in = openStraight(path);
        ASSERT_TRUE(in);
        std::vector<unsigned char> back(grey.pixels.size());
        ASSERT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, back.data()));
        EXPECT_EQ(back, grey.pixels);
    }
}

TEST(Codec, OtherFormatsGoThroughTheOpenImageIoModule) {
    TempDir dir;
    Image image(kW, kH);
    image.fill({0.25f, 2.5f, 0.125f, 1.f});
    ASSERT_TRUE(writeImage(dir.file("x.hdr"), image).ok());
    auto back = readImage(dir.file("x.hdr"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->wasFloat);
    EXPECT_NEAR(back->image.at(3, 4).g, 2.5f, 0.02f);  // RGBE: 8-bit mantissas
    // A file named .png holding a BMP is read by what its bytes are.
    ASSERT_TRUE(writeImage(dir.file("y.bmp"), image).ok());
    std::filesystem::rename(dir.file("y.bmp"), dir.file("y.png"));
    auto misnamed = readImage(dir.file("y.png"));
    ASSERT_TRUE(misnamed.ok()) << misnamed.error().message;
    EXPECT_EQ(linearToSrgb8(misnamed->image.at(0, 0).r), linearToSrgb8(0.25f));
}

TEST(Codec, PngCompressionLevelChangesSizeNotPixels) {
    TempDir dir;
    const Image image = test::imageOf(256, 128, 5, [](int x, int y, auto unit) {
        return Rgba{float(x) / 256.f, unit() * 0.1f, float(y) / 128.f, 1.f};
    });
    std::vector<std::uintmax_t> sizes;
    for (int level : {0, 1, 9}) {
        WriteOptions options;
        options.encode.pngCompression = level;
        const std::string path = dir.file(fileName(3, OIIO::TypeDesc::UINT8, level, ".png"));
        ASSERT_TRUE(writeImage(path, image, options).ok());
        sizes.push_back(std::filesystem::file_size(path));
        auto back = readImage(path);
        ASSERT_TRUE(back.ok());
        for (int x = 0; x < image.width(); ++x)
            ASSERT_EQ(linearToSrgb8(back->image.at(x, 5).g), linearToSrgb8(image.at(x, 5).g));
    }
    EXPECT_GT(sizes[0], std::uintmax_t(256 * 128 * 3));  // stored: every byte plus framing
    EXPECT_LT(sizes[1], sizes[0]);
    EXPECT_LT(sizes[2], sizes[1]);
}

TEST(Codec, ExrZipLevelChangesSizeNotPixels) {
    // Smooth ramps with a little noise: deflate finds more at higher levels. Every level's file
    // reads back through OpenImageIO's own EXR reader to the same halves.
    TempDir dir;
    const Image image = test::imageOf(320, 96, 9, [](int x, int y, auto unit) {
        return Rgba{float(x) / 32.f, unit() * 0.01f + 2.f, float(y % 7), 1.f};
    });
    std::vector<std::uintmax_t> sizes;
    for (int level : {0, 1, 9}) {
        WriteOptions options;
        options.encode.exrCompression = "zip";
        options.encode.exrZipLevel = level;
        const std::string path = dir.file(std::string("zip") + std::to_string(level) + ".exr");
        ASSERT_TRUE(writeImage(path, image, options).ok());
        sizes.push_back(std::filesystem::file_size(path));
        auto in = openStraight(path);
        ASSERT_TRUE(in);
        EXPECT_EQ(in->spec().get_string_attribute("compression"), "zip");
        std::vector<float> back(std::size_t(image.width()) * std::size_t(image.height()) * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()));
        for (int x = 0; x < image.width(); ++x)
            ASSERT_EQ(back[(std::size_t(40) * std::size_t(image.width()) + std::size_t(x)) * 3],
                      float(half(image.at(x, 40).r)));
    }
    EXPECT_GT(sizes[0], std::uintmax_t(320 * 96 * 3 * 2));  // stored: every half plus framing
    EXPECT_LT(sizes[1], sizes[0]);
    EXPECT_LT(sizes[2], sizes[1]);
}

TEST(Codec, HalfConversionsAreImathsBitForBit) {
    // The F16C path (when the CPU has it) against Imath's half, on floats across the whole
    // half range and past it: subnormals, rounding ties, and overflow, which flarekit clamps to
    // the largest finite half where Imath would give infinity.
    const auto inHalfRange = [](float v) { return std::clamp(v, -65504.f, 65504.f); };
    std::vector<float> values;
    for (std::uint32_t bits = 0x33000000u; bits < 0x47900000u; bits += 4099) {
        float v;
        std::memcpy(&v, &bits, 4);
        values.push_back(v);
        values.push_back(-v);
    }
    values.resize(values.size() / 4 * 4);
    // Fewer channels: the first of each pixel's four, packed, and not a half past the end.
    for (const int channels : {1, 2, 3}) {
        const std::size_t pixels = values.size() / 4;
        std::vector<std::uint16_t> packed(pixels * std::size_t(channels) + 1, 0xABCD);
        floatsToHalf(values.data(), pixels, channels, packed.data());
        for (std::size_t p = 0; p < pixels; ++p)
            for (std::size_t c = 0; c < std::size_t(channels); ++c)
                ASSERT_EQ(packed[p * std::size_t(channels) + c],
                          half(inHalfRange(values[p * 4 + c])).bits())
                    << channels << " " << p;
        EXPECT_EQ(packed.back(), 0xABCD) << channels;
    }
    std::vector<std::uint16_t> halves(values.size());
    floatsToHalf(values.data(), values.size() / 4, 4, halves.data());
    std::vector<float> back(values.size());
    halfsToFloats(halves.data(), halves.size(), back.data());
    for (std::size_t i = 0; i < values.size(); ++i) {
        ASSERT_EQ(halves[i], half(inHalfRange(values[i])).bits()) << values[i];
        ASSERT_EQ(back[i], float(half(inHalfRange(values[i])))) << values[i];
    }
    const float odd[4] = {NAN, INFINITY, -INFINITY, 1e6f};
    std::uint16_t out[4];
    floatsToHalf(odd, 1, 4, out);
    // NaN is 0; past 65504, infinities included, the largest finite half (0x7BFF), never Inf.
    EXPECT_EQ(out[0], 0);
    EXPECT_EQ(out[1], 0x7BFF);
    EXPECT_EQ(out[2], 0xFBFF);
    EXPECT_EQ(out[3], 0x7BFF);
    const float edge[4] = {65504.f, 65519.f, 65520.f, -1e30f};  // 65520 would round to Inf
    floatsToHalf(edge, 1, 4, out);
    EXPECT_EQ(out[0], 0x7BFF);
    EXPECT_EQ(out[1], 0x7BFF);
    EXPECT_EQ(out[2], 0x7BFF);
    EXPECT_EQ(out[3], 0xFBFF);
}
