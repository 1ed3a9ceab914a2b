// SPDX-License-Identifier: Apache-2.0
// Colour spaces through OpenColorIO: the shipped config's ACEScg matrix both ways (checked
// against the matrix itself), the sRGB space against flarekit's own curve, linear codes written
// as they are, and the bad names and missing configs.
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "Cli.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {
const std::string kConfig = std::string(FLAREKIT_SAMPLES) + "/../presets/ocio/flarekit.ocio";
//! Rec.709 to ACEScg (Bradford D65 to D60), the matrix the config states.
constexpr double kToAp1[3][3] = {{0.6130974024, 0.3395231462, 0.0473794514},
                                 {0.0701937225, 0.9163538791, 0.0134523985},
                                 {0.0206155929, 0.1095697729, 0.8698146342}};

Image swatches() {
    Image img(4, 2);
    const float values[8][3] = {
        {1, 0, 0},       {0, 1, 0},           {0, 0, 1}, {0.18f, 0.18f, 0.18f},
        {2, 0.5f, 0.1f}, {0.01f, 0.2f, 0.7f}, {8, 8, 8}, {0, 0, 0}};
    for (int i = 0; i < 8; ++i)
        img.at(i % 4, i / 4) = {values[i][0], values[i][1], values[i][2], 1};
    return img;
}

void expectAp1Of(const Image& rec709, const Image& ap1) {
    for (int y = 0; y < rec709.height(); ++y)
        for (int x = 0; x < rec709.width(); ++x) {
            const Rgba &s = rec709.at(x, y), &d = ap1.at(x, y);
            const double in[3] = {s.r, s.g, s.b}, out[3] = {d.r, d.g, d.b};
            for (int r = 0; r < 3; ++r) {
                const double expected =
                    kToAp1[r][0] * in[0] + kToAp1[r][1] * in[1] + kToAp1[r][2] * in[2];
                EXPECT_NEAR(out[r], expected, 1e-5 * std::max(1.0, std::abs(expected)))
                    << x << "," << y << " channel " << r;
            }
        }
}
}  // namespace

TEST(ColorCli, AcescgInAndOutFollowTheConfigsMatrix) {
    TempDir dir;
    WriteOptions f32;
    f32.format = SampleFormat::Float;
    ASSERT_TRUE(writeImage(dir.file("rec709.exr"), swatches(), f32));
    // Out: the working-space swatches written in ACEScg are the matrix times them.
    CliResult r = runCli({"apply", dir.file("rec709.exr"), "-o", dir.file("ap1.exr"), "--depth",
                          "float", "--light", "1,1", "--intensity", "0", "--colorspace-out",
                          "acescg", "--ocio-config", kConfig});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto ap1 = readImage(dir.file("ap1.exr"));
    expectAp1Of(swatches(), ap1->image);
    // In: ACEScg read back into the working space gives the swatches again.
    r = runCli({"apply", dir.file("ap1.exr"), "-o", dir.file("back.exr"), "--depth", "float",
                "--light", "1,1", "--intensity", "0", "--colorspace-in", "acescg", "--ocio-config",
                kConfig});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto back = readImage(dir.file("back.exr"));
    const Image original = swatches();
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            EXPECT_NEAR(back->image.at(x, y).r, original.at(x, y).r,
                        1e-5 * (1 + original.at(x, y).r));
            EXPECT_NEAR(back->image.at(x, y).b, original.at(x, y).b,
                        1e-5 * (1 + original.at(x, y).b));
        }
}

TEST(ColorCli, SrgbMatchesFlarekitsCurveAndLinearCodesAreWrittenAsTheyAre) {
    TempDir dir;
    const std::string png = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
    ASSERT_EQ(runCli({"apply", png, "-o", dir.file("default.png")}).exitCode, 0);
    CliResult r = runCli({"apply", png, "-o", dir.file("ocio.png"), "--colorspace-in", "srgb",
                          "--colorspace-out", "srgb", "--ocio-config", kConfig});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto a = readImage8(dir.file("default.png")), b = readImage8(dir.file("ocio.png"));
    ASSERT_TRUE(a && b);
    int worst = 0;
    for (std::size_t i = 0; i < a->pixels.size(); ++i)
        worst = std::max(worst, std::abs(int(a->pixels[i]) - int(b->pixels[i])));
    EXPECT_LE(worst, 1);  // OpenColorIO's float curve against flarekit's correctly rounded one
    // Linear out: the codes are the working values x 255, no sRGB curve.
    Image grey(2, 1);
    grey.at(0, 0) = {0.5f, 0.25f, 0.125f, 1};
    grey.at(1, 0) = {1, 0, 0.75f, 1};
    WriteOptions f32;
    f32.format = SampleFormat::Float;
    ASSERT_TRUE(writeImage(dir.file("grey.exr"), grey, f32));
    r = runCli({"apply", dir.file("grey.exr"), "-o", dir.file("linear.png"), "--light", "0,0",
                "--intensity", "0", "--tonemap", "none", "--colorspace-out", "lin_rec709",
                "--ocio-config", kConfig});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto codes = readImage8(dir.file("linear.png"));
    ASSERT_TRUE(codes);
    const int c = codes->channels;
    EXPECT_EQ(codes->pixels[0], 128);
    EXPECT_EQ(codes->pixels[1], 64);
    EXPECT_EQ(codes->pixels[2], 32);
    EXPECT_EQ(codes->pixels[std::size_t(c) + 2], 191);
}

TEST(ColorCli, UnknownNamesListTheConfigsSpacesAndAMissingConfigIsNamed) {
    TempDir dir;
    const std::string png = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
    CliResult r = runCli({"apply", png, "-o", dir.file("x.png"), "--colorspace-in", "ACES - ACEScg",
                          "--ocio-config", kConfig});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("it has: lin_rec709, srgb, acescg, raw"), std::string::npos) << r.err;
    r = runCli({"postfx", png, "-o", dir.file("x.png"), "--colorspace-out", "srgb", "--ocio-config",
                dir.file("none.ocio")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("not a usable OpenColorIO config"), std::string::npos) << r.err;
    // Without $OCIO the shipped config is found beside flarekit (here: its build tree; the
    // package test does the same from a moved install): its colour space names are accepted.
    ::unsetenv("OCIO");
    r = runCli({"apply", png, "-o", dir.file("shipped.png"), "--colorspace-in", "acescg"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"apply", png, "-o", dir.file("x.png"), "--colorspace-in", "nonesuch"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("flarekit.ocio; it has: lin_rec709, srgb, acescg, raw"), std::string::npos)
        << r.err;
    // $OCIO is the default config.
    ::setenv("OCIO", kConfig.c_str(), 1);
    r = runCli({"apply", png, "-o", dir.file("ok.png"), "--colorspace-in", "srgb"});
    ::unsetenv("OCIO");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(dir.entries(), 2u);
}

TEST(ColorCli, AnOutputInAnotherColourSpaceIsTaggedWithItsNameAndPrimaries) {
    TempDir dir;
    const std::string exr = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";
    CliResult r = runCli({"postfx", exr, "-o", dir.file("cg.exr"), "--colorspace-out", "acescg",
                          "--ocio-config", kConfig});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"postfx", exr, "-o", dir.file("plain.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    {
        Imf::InputFile file(dir.file("cg.exr").c_str());
        const Imf::Header& h = file.header();
        const auto* name = h.findTypedAttribute<Imf::StringAttribute>("oiio:ColorSpace");
        ASSERT_NE(name, nullptr);
        EXPECT_EQ(name->value(), "acescg");
        ASSERT_TRUE(Imf::hasChromaticities(h));
        // ACEScg's AP1 primaries and the ACES white point (SMPTE ST 2065-1, S-2014-004).
        const Imf::Chromaticities& c = Imf::chromaticities(h);
        EXPECT_FLOAT_EQ(c.red.x, 0.713f);
        EXPECT_FLOAT_EQ(c.red.y, 0.293f);
        EXPECT_FLOAT_EQ(c.green.x, 0.165f);
        EXPECT_FLOAT_EQ(c.green.y, 0.830f);
        EXPECT_FLOAT_EQ(c.blue.x, 0.128f);
        EXPECT_FLOAT_EQ(c.blue.y, 0.044f);
        EXPECT_FLOAT_EQ(c.white.x, 0.32168f);
        EXPECT_FLOAT_EQ(c.white.y, 0.33767f);
    }
    {
        // Without --colorspace-out the output is flarekit's scene-linear Rec.709, untagged.
        Imf::InputFile file(dir.file("plain.exr").c_str());
        EXPECT_EQ(file.header().findTypedAttribute<Imf::StringAttribute>("oiio:ColorSpace"),
                  nullptr);
        EXPECT_FALSE(Imf::hasChromaticities(file.header()));
    }
}
