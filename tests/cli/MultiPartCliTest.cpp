// SPDX-License-Identifier: Apache-2.0
// Multi-part EXRs (stereo views, a compositor's layers): the part flared is the one --part names
// (the first by default), every other part reaches the EXR output bit for bit, and an output
// that cannot hold parts is refused naming them.
#include <ImfChannelList.h>
#include <ImfDeepFrameBuffer.h>
#include <ImfDeepScanLineOutputFile.h>
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
#include <fstream>
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

//! Scanline parts of these names, each its own view.
void writeParts(const std::string& path, const std::vector<const char*>& names) {
    std::vector<Imf::Header> headers;
    for (const char* name : names) headers.push_back(partHeader(name, Imf::SCANLINEIMAGE));
    Imf::MultiPartOutputFile file(path.c_str(), headers.data(), int(headers.size()));
    for (int i = 0; i < int(names.size()); ++i) {
        std::vector<half> px = viewPixels(i);
        Imf::OutputPart part(file, i);
        part.setFrameBuffer(rgbaFrame(px));
        part.writePixels(kH);
    }
}

//! A part of `channels` (half), each channel the view's red, green, blue or alpha by its suffix.
Imf::Header namedChannelsPart(const char* name, const std::vector<std::string>& channels) {
    Imf::Header h(kW, kH);
    h.setName(name);
    h.setType(Imf::SCANLINEIMAGE);
    h.compression() = Imf::ZIP_COMPRESSION;
    for (const std::string& c : channels) h.channels().insert(c, Imf::Channel(Imf::HALF));
    return h;
}

//! Parts "beauty" (R, G, B, A), "diffuse" (diffuse.R, .G, .B, .A, as Nuke writes a layer to a
//! part) and "depth" (Z only), each filled with view 0, 1 and 2's pixels.
void writeLayerParts(const std::string& path) {
    const std::vector<std::vector<std::string>> channels = {
        {"R", "G", "B", "A"}, {"diffuse.R", "diffuse.G", "diffuse.B", "diffuse.A"}, {"Z"}};
    const char* names[] = {"beauty", "diffuse", "depth"};
    std::vector<Imf::Header> headers;
    for (int i = 0; i < 3; ++i) headers.push_back(namedChannelsPart(names[i], channels[i]));
    Imf::MultiPartOutputFile file(path.c_str(), headers.data(), 3);
    for (int i = 0; i < 3; ++i) {
        std::vector<half> px = viewPixels(i);
        Imf::FrameBuffer fb;
        for (const std::string& c : channels[std::size_t(i)]) {
            const int lane = std::string("RGBAZ").find(c.back()) % 4;
            fb.insert(c, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(px.data() + lane),
                                    4 * sizeof(half), 4 * sizeof(half) * kW));
        }
        Imf::OutputPart part(file, i);
        part.setFrameBuffer(fb);
        part.writePixels(kH);
    }
}

// A part whose colour is one layer's (diffuse.R, ...) is flared as a plain part is and keeps its
// channel names; a part with no colour (only Z) is one line naming the file, the part and its
// channels.
TEST(CliMultiPart, ALayerNamedPartIsFlaredUnderItsOwnNames) {
    TempDir dir;
    const std::string in = dir.file("layers.exr");
    writeLayerParts(in);
    const CliResult r = runCli({"postfx", in, "-o", dir.file("o.exr"), "--part", "diffuse"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Imf::MultiPartInputFile out(dir.file("o.exr").c_str());
    ASSERT_EQ(out.parts(), 3);
    std::vector<std::string> names;
    for (auto c = out.header(1).channels().begin(); c != out.header(1).channels().end(); ++c)
        names.push_back(c.name());
    EXPECT_EQ(names,
              (std::vector<std::string>{"diffuse.A", "diffuse.B", "diffuse.G", "diffuse.R"}));
    EXPECT_TRUE(samePixels(partPixels(dir.file("o.exr"), 0), partPixels(in, 0)));
    // Read back by name: the flared view, brighter than the input's somewhere.
    auto flared = readImage(dir.file("o.exr"), {}, {"diffuse"});
    auto plate = readImage(in, {}, {"diffuse"});
    ASSERT_TRUE(flared && plate);
    double added = 0;
    for (std::size_t i = 0; i < plate->image.pixelCount() * 4; i += 4)
        added += flared->image.data()[i + 1] - plate->image.data()[i + 1];
    EXPECT_GT(added, 0.0);
    const CliResult z = runCli({"postfx", in, "-o", dir.file("z.exr"), "--part", "depth"});
    EXPECT_EQ(z.exitCode, 2);
    EXPECT_EQ(lineCount(z.err), 1) << z.err;
    EXPECT_NE(z.err.find(in + ": part 'depth' has channels Z; flarekit flares R,G,B(,A)"),
              std::string::npos)
        << z.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("z.exr")));
}

// Names from the file reach the terminal escaped: an escape sequence (here one that sets the
// terminal's title) and a newline in a part's name print as \xNN, on one line.
TEST(CliMultiPart, PartNamesReachTheTerminalEscaped) {
    TempDir dir;
    const std::string in = dir.file("hostile.exr");
    writeParts(in, {"\x1b]0;owned\x07", "two\nlines\xff"});
    const CliResult r = runCli({"postfx", in, "-o", dir.file("o.exr"), "--part", "x"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("0 '\\x1b]0;owned\\x07', 1 'two\\x0alines\\xff'"), std::string::npos)
        << r.err;
}

//! A single-part deep file (Z only, no samples): what a renderer's deep output looks like.
void writeDeep(const std::string& path) {
    Imf::Header h(8, 4);
    h.setType(Imf::DEEPSCANLINE);
    h.compression() = Imf::ZIPS_COMPRESSION;
    h.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    Imf::DeepScanLineOutputFile file(path.c_str(), h);
    std::vector<unsigned> counts(32, 0);
    std::vector<float*> z(32, nullptr);
    Imf::DeepFrameBuffer frame;
    frame.insertSampleCountSlice(Imf::Slice(Imf::UINT, reinterpret_cast<char*>(counts.data()),
                                            sizeof(unsigned), sizeof(unsigned) * 8));
    frame.insert("Z", Imf::DeepSlice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float*),
                                     sizeof(float*) * 8, sizeof(float)));
    file.setFrameBuffer(frame);
    file.writePixels(4);
}

// A deep image is not flattened behind the user's back: one line saying so and how to flatten.
TEST(CliMultiPart, ADeepImageIsRefusedNotFlattened) {
    TempDir dir;
    writeDeep(dir.file("deep.exr"));
    const CliResult r = runCli({"postfx", dir.file("deep.exr"), "-o", dir.file("o.exr")});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(dir.file("deep.exr") + ": a deep image (deepscanline)"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.exr")));
}

// A flared tiled part stays tiled, in its tile size.
TEST(CliMultiPart, AFlaredTiledPartKeepsItsTiles) {
    TempDir dir;
    const std::string in = dir.file("stereo.exr");
    writeStereo(in);
    const CliResult r = runCli({"postfx", in, "-o", dir.file("o.exr"), "--part", "matte"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Imf::MultiPartInputFile out(dir.file("o.exr").c_str());
    ASSERT_EQ(out.header(2).type(), Imf::TILEDIMAGE);
    EXPECT_EQ(out.header(2).tileDescription().xSize, 16u);
    EXPECT_EQ(out.header(2).tileDescription().ySize, 16u);
    EXPECT_FALSE(samePixels(partPixels(dir.file("o.exr"), 2), partPixels(in, 2)));
}

// A part copied chunk for chunk is decoded first: two flipped bytes in the tiled part's last
// tile (its ZIP data) are exit 2 naming that part, never an output that fails to open.
TEST(CliMultiPart, ACorruptPartIsRefusedNotCopied) {
    TempDir dir;
    const std::string in = dir.file("stereo.exr");
    writeStereo(in);
    std::string bytes = slurp(in);
    for (std::size_t at : {bytes.size() - 40, bytes.size() - 39}) bytes[at] = char(~bytes[at]);
    std::ofstream(dir.file("corrupt.exr"), std::ios::binary)
        .write(bytes.data(), std::streamsize(bytes.size()));
    const CliResult r =
        runCli({"postfx", dir.file("corrupt.exr"), "-o", dir.file("o.exr"), "--part", "right"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(dir.file("corrupt.exr") + ": part 'matte' (copied unchanged to the "
                                                   "output) does not decode"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.exr")));
}

// Parts named "1" (index 0) and "0" (index 1): a name that matches wins, "#N" is the index.
TEST(CliMultiPart, NumericPartNamesAreNamesAndHashIsTheIndex) {
    TempDir dir;
    const std::string in = dir.file("numbered.exr");
    writeParts(in, {"1", "0"});
    for (const auto& [part, flared] :
         {std::pair{"0", 1}, std::pair{"1", 0}, std::pair{"#0", 0}, std::pair{"#1", 1}}) {
        const std::string out = dir.file(std::string("o") + (part[0] == '#' ? "h" : "") +
                                         part[std::string(part).size() - 1] + ".exr");
        const CliResult r = runCli({"postfx", in, "-o", out, "--part", part});
        ASSERT_EQ(r.exitCode, 0) << part << ": " << r.err;
        EXPECT_FALSE(samePixels(partPixels(out, flared), partPixels(in, flared)))
            << "--part " << part << " did not flare part " << flared;
        EXPECT_TRUE(samePixels(partPixels(out, 1 - flared), partPixels(in, 1 - flared)))
            << "--part " << part << " flared part " << 1 - flared;
    }
    const CliResult r = runCli({"postfx", in, "-o", dir.file("x.exr"), "--part", "#2"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--part #2: " + in + " has no such part (2: 0 '1', 1 '0')"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace flarekit::test
