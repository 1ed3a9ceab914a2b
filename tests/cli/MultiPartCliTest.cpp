// SPDX-License-Identifier: Apache-2.0
// Multi-part EXRs (stereo views, a compositor's layers): the part flared is the one --part names
// (the first by default), every other part reaches the EXR output bit for bit, and an output
// that cannot hold parts is refused naming them.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfTiledInputPart.h>
#include <ImfTiledOutputPart.h>
#include <gtest/gtest.h>
#include <half.h>

#include <filesystem>
#include <vector>

#include "Cli.h"
#include "flarekit/ImageIO.h"

namespace flarekit::test {
namespace {

constexpr int kW = 64, kH = 40;

//! A part's RGBA halves: a dim sky and a sun of 40 at (20 + 20 * seed, 20), so each view differs.
std::vector<half> viewPixels(int seed) {
    std::vector<half> px(std::size_t(kW) * kH * 4);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float dx = float(x) + 0.5f - float(20 + 20 * seed), dy = float(y) + 0.5f - 20.f;
            const float v = dx * dx + dy * dy < 9.f ? 40.f : 0.05f + 0.002f * float(x + seed);
            for (int c = 0; c < 3; ++c)
                px[(std::size_t(y) * kW + x) * 4 + c] = half(v * (1.f - 0.1f * float(c)));
            px[(std::size_t(y) * kW + x) * 4 + 3] = half(1.f);
        }
    return px;
}

Imf::Header partHeader(const char* name, const std::string& type) {
    Imf::Header h(kW, kH);
    h.setName(name);
    h.setType(type);
    h.compression() = Imf::ZIP_COMPRESSION;
    if (type == Imf::TILEDIMAGE) h.setTileDescription(Imf::TileDescription(16, 16));
    for (const char* c : {"R", "G", "B", "A"}) h.channels().insert(c, Imf::Channel(Imf::HALF));
    return h;
}

Imf::FrameBuffer rgbaFrame(std::vector<half>& px) {
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
        fb.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(px.data() + c),
                                       4 * sizeof(half), 4 * sizeof(half) * kW));
    return fb;
}

//! left (scanline), right (scanline), matte (tiled): three parts of one shot.
void writeStereo(const std::string& path) {
    const Imf::Header headers[] = {partHeader("left", Imf::SCANLINEIMAGE),
                                   partHeader("right", Imf::SCANLINEIMAGE),
                                   partHeader("matte", Imf::TILEDIMAGE)};
    Imf::MultiPartOutputFile file(path.c_str(), headers, 3);
    for (int i = 0; i < 2; ++i) {
        std::vector<half> px = viewPixels(i);
        Imf::OutputPart part(file, i);
        part.setFrameBuffer(rgbaFrame(px));
        part.writePixels(kH);
    }
    std::vector<half> px = viewPixels(2);
    Imf::TiledOutputPart tiled(file, 2);
    tiled.setFrameBuffer(rgbaFrame(px));
    tiled.writeTiles(0, tiled.numXTiles() - 1, 0, tiled.numYTiles() - 1);
}

//! A part's RGBA as the file stores it.
std::vector<half> partPixels(const std::string& path, int index) {
    Imf::MultiPartInputFile file(path.c_str());
    std::vector<half> px(std::size_t(kW) * kH * 4);
    Imf::InputPart part(file, index);
    part.setFrameBuffer(rgbaFrame(px));
    part.readPixels(0, kH - 1);
    return px;
}

std::vector<std::string> partNames(const std::string& path) {
    Imf::MultiPartInputFile file(path.c_str());
    std::vector<std::string> names;
    for (int i = 0; i < file.parts(); ++i) names.push_back(file.header(i).name());
    return names;
}

bool samePixels(const std::vector<half>& a, const std::vector<half>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].bits() != b[i].bits()) return false;
    return true;
}

TEST(CliMultiPart, ThePartNamedIsFlaredAndTheOthersPassThroughBitForBit) {
    TempDir dir;
    const std::string in = dir.file("stereo.exr");
    writeStereo(in);
    for (const char* command : {"apply", "postfx"}) {
        const std::string out = dir.file(std::string(command) + ".exr");
        std::vector<std::string> args{command, in, "-o", out, "--part", "right"};
        if (std::string(command) == "apply") args.insert(args.end(), {"--light", "40.5,20.5"});
        const CliResult r = runCli(args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(partNames(out), (std::vector<std::string>{"left", "right", "matte"})) << command;
        EXPECT_TRUE(samePixels(partPixels(out, 0), partPixels(in, 0))) << command << ": left";
        EXPECT_TRUE(samePixels(partPixels(out, 2), partPixels(in, 2))) << command << ": matte";
        EXPECT_FALSE(samePixels(partPixels(out, 1), partPixels(in, 1))) << command << ": right";
        // The part flared is what flaring that view alone gives, read back by name.
        auto view = readImage(out, {}, {"right"});
        ASSERT_TRUE(view) << view.error().message;
        EXPECT_EQ(view->exrParts, (std::vector<std::string>{"left", "right", "matte"}));
    }
    // By index, and the first part by default.
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("i.exr"), "--light", "20.5,20.5", "--part", "0"})
                  .exitCode,
              0);
    ASSERT_EQ(runCli({"apply", in, "-o", dir.file("d.exr"), "--light", "20.5,20.5"}).exitCode, 0);
    EXPECT_EQ(slurp(dir.file("i.exr")), slurp(dir.file("d.exr")));
    EXPECT_FALSE(samePixels(partPixels(dir.file("d.exr"), 0), partPixels(in, 0)));
    EXPECT_TRUE(samePixels(partPixels(dir.file("d.exr"), 1), partPixels(in, 1)));
}

TEST(CliMultiPart, AnOutputWithoutPartsOrAnUnknownPartIsOneLineAndNoFile) {
    TempDir dir;
    const std::string in = dir.file("stereo.exr");
    writeStereo(in);
    CliResult r = runCli({"apply", in, "-o", dir.file("x.png"), "--light", "20,20"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("a multi-part EXR (3 parts: left, right, matte)"), std::string::npos)
        << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    r = runCli({"postfx", in, "-o", dir.file("y.exr"), "--part", "centre"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--part centre: " + in +
                         " has no such part (3: 0 'left', 1 'right', 2 'matte')"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("y.exr")));
    r = runCli({"postfx", kSunset, "-o", dir.file("z.png"), "--part", "left"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is not a multi-part EXR"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace flarekit::test
