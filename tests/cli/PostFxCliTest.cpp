// SPDX-License-Identifier: Apache-2.0
// flarekit postfx as a user runs it: both backends, every preset, layers, and bad
// input (grey and 2-channel inputs promoted, more than 4 channels refused in one line).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "Cli.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

//! Writes a `channels`-channel 8-bit PNG or float EXR with a bright spot, through OIIO.
void writeChannels(const std::string& path, int channels, bool floatFile) {
    const int w = 96, h = 64;
    std::vector<float> px(std::size_t(w * h * channels), 0.1f);
    for (int y = 20; y < 26; ++y) {
        for (int x = 60; x < 66; ++x) {
            for (int c = 0; c < channels; ++c)
                px[std::size_t((y * w + x) * channels + c)] = floatFile ? 40.f : 1.f;
        }
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, channels, floatFile ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
}

int channelsOf(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    return in ? in->spec().nchannels : -1;
}

}  // namespace

FLAREKIT_GL_TEST(PostFxCli, EveryPresetOnBothBackendsAgreesWithinOneLevel) {
    TempDir dir;
    for (const char* preset : {"killzone2", "modern", "anamorphic", "subtle", "photo"}) {
        const std::string cpu = dir.file(std::string(preset) + "-cpu.png"),
                          gl = dir.file(std::string(preset) + "-gl.png");
        auto r = runCli({"postfx", kSunsetHdr, "-o", cpu, "--preset", preset, "--tonemap", "aces"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        r = runCli({"postfx", kSunsetHdr, "-o", gl, "--preset", preset, "--tonemap", "aces",
                    "--backend", "gl"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        auto a = readImage8(cpu), b = readImage8(gl);
        ASSERT_TRUE(a.ok() && b.ok());
        ASSERT_EQ(a->pixels.size(), b->pixels.size());
        int worst = 0;
        for (std::size_t i = 0; i < a->pixels.size(); ++i)
            worst = std::max(worst, std::abs(int(a->pixels[i]) - int(b->pixels[i])));
        EXPECT_LE(worst, 1) << preset;
    }
}

TEST(PostFxCli, HdrStaysLinearAndLayersAreWritten) {
    TempDir dir;
    const std::string out = dir.file("flare.exr"), layers = dir.file("layers");
    auto r = runCli(
        {"postfx", kSunsetHdr, "-o", out, "--preset", "modern", "--save-layers", layers, "-v"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("ghosts"), std::string::npos) << r.out;  // -v prints the pass times
    auto image = readImage(out);
    ASSERT_TRUE(image.ok());
    float peak = 0;
    for (std::size_t i = 0; i < image->image.pixelCount() * 4; ++i)
        peak = std::max(peak, image->image.data()[i]);
    EXPECT_GT(peak, 10.f);  // the sun is still HDR: no tone curve on a float output by default
    for (const char* layer : {"bloom", "ghosts", "halo", "streaks", "lens", "final"}) {
        const std::string path = layers + "/" + layer + ".exr";
        auto l = readImage(path);
        ASSERT_TRUE(l.ok()) << path;
        EXPECT_EQ(l->image.width(), image->image.width()) << layer;
    }
}

TEST(PostFxCli, GreyAndGreyAlphaArePromoted) {
    TempDir dir;
    for (int channels : {1, 2}) {
        const std::string in = dir.file("in" + std::to_string(channels) + ".png"),
                          out = dir.file("out" + std::to_string(channels) + ".png");
        writeChannels(in, channels, false);
        auto r = runCli({"postfx", in, "-o", out, "--preset", "subtle"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(channelsOf(out), channels == 2 ? 4 : 3) << "grey -> RGB, grey+alpha -> RGBA";
    }
}

TEST(PostFxCli, MoreThanFourChannelsOutsideAnExrIsAClearError) {
    // An EXR's channels past RGBA pass through to an EXR output (ShotCli); other formats'
    // cannot be written back, so the input is refused rather than silently losing them.
    TempDir dir;
    const std::string in = dir.file("six.tif");
    writeChannels(in, 6, false);
    const std::size_t before = dir.entries();
    auto r = runCli({"postfx", in, "-o", dir.file("out.exr")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("6 channels"), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), before);
}

TEST(PostFxCli, ApplyTreatsMoreThanFourChannelsThePostFxWay) {
    // One behaviour for one situation: both subcommands refuse a non-EXR in the same one line,
    // and both pass an EXR's extra channels through.
    TempDir dir;
    const std::string in = dir.file("six.tif");
    writeChannels(in, 6, false);
    const std::size_t before = dir.entries();
    auto apply = runCli({"apply", in, "-o", dir.file("out.exr")});
    auto postfx = runCli({"postfx", in, "-o", dir.file("out.exr")});
    EXPECT_EQ(apply.exitCode, 2);
    EXPECT_EQ(apply.err, postfx.err);
    EXPECT_EQ(dir.entries(), before);
    const std::string exr = dir.file("six.exr");
    writeChannels(exr, 6, true);
    ASSERT_EQ(runCli({"apply", exr, "-o", dir.file("a.exr")}).exitCode, 0);
    ASSERT_EQ(runCli({"postfx", exr, "-o", dir.file("p.exr")}).exitCode, 0);
    EXPECT_EQ(channelsOf(dir.file("a.exr")), 6);
    EXPECT_EQ(channelsOf(dir.file("p.exr")), 6);
}

TEST(PostFxCli, BadInputExitsTwoWithOneLineAndWritesNothing) {
    TempDir dir;
    const std::string corrupt = dir.file("corrupt.png");
    { std::ofstream(corrupt) << "\x89PNG\r\n\x1a\n not really"; }
    const std::string badPreset = dir.file("bad.json");
    { std::ofstream(badPreset) << R"({"ghosts": [{"scale": 2, "samples": 0}]})"; }
    const std::size_t before = dir.entries();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"postfx", corrupt, "-o", dir.file("o.png")}, "corrupt.png"},
        {{"postfx", dir.file("missing.exr"), "-o", dir.file("o.png")}, "missing.exr"},
        {{"postfx", kSunset, "-o", dir.file("o.png"), "--preset", "nope"},
         "expected a JSON file or one of: anamorphic, killzone2, modern, photo, subtle"},
        {{"postfx", kSunset, "-o", dir.file("o.png"), "--preset", badPreset},
         "ghosts[0].samples: expected an integer in [1, 64], got 0"},
        {{"postfx", kSunset, "-o", kSunset + std::string("/o.png")},
         "sunset.png' is not a directory"},
    };
    for (const auto& [args, mention] : cases) {
        auto r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << args[1] << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos)
            << "expected '" << mention << "' in: " << r.err;
    }
    EXPECT_EQ(dir.entries(), before);
    auto r = runCli({"postfx", kSunset, "-o", dir.file("o.png"), "--backend", "vulkan"});
    EXPECT_NE(r.exitCode, 0);
}

namespace {
//! Share of pixels whose 8-bit value moved by more than `levels` in any channel.
double shareChanged(const flarekit::Image8& a, const flarekit::Image8& b, int levels) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        n += i % std::size_t(a.channels) < 3 &&
             std::abs(int(a.pixels[i]) - int(b.pixels[i])) > levels;
    return double(n) / double(a.pixels.size() / std::size_t(a.channels));
}
}  // namespace

// An 8-bit photo's sun is clipped at 1, barely above the threshold: the default chain hardly
// touches it. --expand-highlights gives the clipped light back its energy, so it flares, while
// the output keeps the photo's own pixels where nothing flares (the expansion is taken back off).
TEST(PostFxCli, ExpandHighlightsMakesAnEightBitSunFlare) {
    TempDir dir;
    const std::string plain = dir.file("plain.png"), expanded = dir.file("expanded.png");
    ASSERT_EQ(runCli({"postfx", kSunset, "-o", plain}).exitCode, 0);
    const CliResult r = runCli({"postfx", kSunset, "-o", expanded, "--expand-highlights"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto in = readImage8(kSunset), a = readImage8(plain), b = readImage8(expanded);
    ASSERT_TRUE(in.ok() && a.ok() && b.ok());
    EXPECT_LT(shareChanged(*in, *a, 30), 0.001);
    EXPECT_GT(shareChanged(*in, *b, 30), 0.02);
    // The clipped sun disc itself stays white, not pushed past it.
    const std::size_t sun = (std::size_t(250) * 1280 + 930) * std::size_t(b->channels);
    EXPECT_EQ(b->pixels[sun], 255);
    // HDR input has its own highlights: a warning, and the same picture as without the flag.
    const CliResult h =
        runCli({"postfx", kSunsetHdr, "-o", dir.file("h.exr"), "--expand-highlights"});
    EXPECT_EQ(h.exitCode, 0);
    EXPECT_NE(h.err.find("--expand-highlights is for 8/16-bit input"), std::string::npos) << h.err;
    // A gain is a number, fractions kept (4.5 is not 4), in [1, 10000].
    const CliResult bad =
        runCli({"postfx", kSunset, "-o", dir.file("b.png"), "--expand-highlights=big"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--expand-highlights: expected a gain in [1, 10000], got 'big'"),
              std::string::npos)
        << bad.err;
    const std::string g4 = dir.file("g4.png"), g45 = dir.file("g45.png");
    ASSERT_EQ(runCli({"postfx", kSunset, "-o", g4, "--expand-highlights=4"}).exitCode, 0);
    ASSERT_EQ(runCli({"postfx", kSunset, "-o", g45, "--expand-highlights=4.5"}).exitCode, 0);
    auto i4 = readImage8(g4), i45 = readImage8(g45);
    ASSERT_TRUE(i4.ok() && i45.ok());
    EXPECT_GT(shareChanged(*i4, *i45, 2), 0.001);
}
