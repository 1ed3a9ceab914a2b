// SPDX-License-Identifier: Apache-2.0
// What a shot writes: the flare's passes summing to the flare and the composite exactly input +
// flare; an EXR plate's channels, attributes, windows and compression passed through; its extra
// channels counted in the memory budget.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfTimeCodeAttribute.h>
#include <gtest/gtest.h>
#include <half.h>

#include "ShotFixtures.h"

using namespace flarekit;
using namespace flarekit::test;
using namespace flarekit::test::shot;

TEST(ShotCli, LayersSumToTheFlareAndTheCompositeIsInputPlusFlareExactly) {
    TempDir in, out;
    writeShot(in, 2);
    const std::string layers = out.file("layers");
    CliResult r = runCli({"apply", in.file("in.0001.exr"), "-o", out.file("comp.exr"), "--depth",
                          "float", "--light", "100.5,45.5", "--layers", layers});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto input = readImage(in.file("in.0001.exr"));
    auto comp = readImage(out.file("comp.exr"));
    auto flare = readImage(layers + "/flare.exr");
    ASSERT_TRUE(input && comp && flare);
    // The passes the preset has, summed in their order, are the flare; input + flare is the
    // composite, both bit for bit.
    Image sum(kW, kH);
    int passes = 0;
    for (const char* name : {"glow", "halo", "ghosts", "streaks", "starburst"}) {
        auto layer = readImage(layers + "/" + name + ".exr");
        if (!layer) continue;
        ++passes;
        for (std::size_t i = 0; i < sum.pixelCount() * 4; ++i)
            sum.data()[i] += layer->image.data()[i];
    }
    EXPECT_GE(passes, 3);
    double flareLight = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const Rgba &f = flare->image.at(x, y), &s = sum.at(x, y), &i = input->image.at(x, y),
                       &c = comp->image.at(x, y);
            ASSERT_EQ(f.r, s.r);
            ASSERT_EQ(f.g, s.g);
            ASSERT_EQ(c.r, i.r + f.r);
            ASSERT_EQ(c.g, i.g + f.g);
            ASSERT_EQ(c.b, i.b + f.b);
            flareLight += f.g;
        }
    EXPECT_GT(flareLight, 10.0);
    // --flare-only writes that flare alone.
    r = runCli({"apply", in.file("in.0001.exr"), "-o", out.file("only.exr"), "--depth", "float",
                "--light", "100.5,45.5", "--flare-only"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto only = readImage(out.file("only.exr"));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) ASSERT_EQ(only->image.at(x, y).g, flare->image.at(x, y).g);
    // A sequence's passes are sequences of their own.
    r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("c.####.exr"), "--light",
                "100.5,45.5", "--layers", out.file("seq")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out.file("seq/flare.0002.exr")));
    EXPECT_TRUE(fs::exists(out.file("seq/glow.0001.exr")));
}

TEST(ShotCli, AnExrPlatesChannelsAttributesWindowsAndCompressionPassThrough) {
    TempDir dir;
    // A plate with a data window inside a larger display window, two channels past RGBA (a
    // float depth and a half matte), a timecode, a custom attribute, ZIP and float colour.
    const Imath::Box2i display({0, 0}, {99, 59}), data({10, 5}, {89, 54});
    const int w = 80, h = 50;
    std::vector<float> rgba(std::size_t(w * h * 4), 0.2f), depth(std::size_t(w * h));
    std::vector<half> matte(std::size_t(w * h));
    for (int i = 0; i < w * h; ++i) {
        depth[std::size_t(i)] = 100.f + float(i);
        matte[std::size_t(i)] = half(float(i % 7) / 7.f);
        rgba[std::size_t(i) * 4 + 3] = 1.f;
    }
    rgba[std::size_t(20 * w + 40) * 4] = 500.f;  // a light for postfx to flare
    {
        Imf::Header header(display, data, 1.f, Imath::V2f(0, 0), 1.f, Imf::INCREASING_Y,
                           Imf::ZIP_COMPRESSION);
        header.insert("timeCode", Imf::TimeCodeAttribute(Imf::TimeCode(1, 2, 3, 4)));
        header.insert("studio/shot", Imf::StringAttribute("sh010"));
        writeExrPlate(dir.file("plate.1001.exr"), header, rgba, "depth.Z", depth, "matte.A", matte);
    }
    for (const char* job : {"apply", "postfx"}) {
        const std::string out = dir.file(std::string(job) + ".####.exr");
        const CliResult r =
            job == std::string("apply")
                ? runCli({job, dir.file("plate.####.exr"), "-o", out, "--light", "40.5,20.5"})
                : runCli({job, dir.file("plate.####.exr"), "-o", out});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        Imf::InputFile file(dir.file(std::string(job) + ".1001.exr").c_str());
        const Imf::Header& header = file.header();
        EXPECT_EQ(header.displayWindow(), display) << job;
        EXPECT_EQ(header.dataWindow(), data) << job;
        EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION) << job;
        EXPECT_EQ(header.channels().findChannel("R")->type, Imf::FLOAT) << job;
        ASSERT_NE(header.findTypedAttribute<Imf::TimeCodeAttribute>("timeCode"), nullptr) << job;
        EXPECT_EQ(header.typedAttribute<Imf::TimeCodeAttribute>("timeCode").value().frame(), 4);
        ASSERT_NE(header.findTypedAttribute<Imf::StringAttribute>("studio/shot"), nullptr) << job;
        EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("studio/shot").value(), "sh010");
        ASSERT_NE(header.channels().findChannel("depth.Z"), nullptr) << job;
        EXPECT_EQ(header.channels().findChannel("matte.A")->type, Imf::HALF) << job;
        std::vector<float> z(std::size_t(w * h));
        std::vector<half> m(std::size_t(w * h));
        std::vector<float> red(std::size_t(w * h));
        Imf::FrameBuffer fb;
        fb.insert("depth.Z",
                  Imf::Slice::Make(Imf::FLOAT, z.data(), data, sizeof(float), sizeof(float) * w));
        fb.insert("matte.A",
                  Imf::Slice::Make(Imf::HALF, m.data(), data, sizeof(half), sizeof(half) * w));
        fb.insert("R",
                  Imf::Slice::Make(Imf::FLOAT, red.data(), data, sizeof(float), sizeof(float) * w));
        file.setFrameBuffer(fb);
        file.readPixels(data.min.y, data.max.y);
        EXPECT_EQ(z, depth) << job;
        for (std::size_t i = 0; i < m.size(); ++i) ASSERT_EQ(float(m[i]), float(matte[i])) << job;
        double added = 0;
        for (std::size_t i = 0; i < red.size(); ++i) added += red[i] - rgba[i * 4];
        EXPECT_GT(added, 1.0) << job << ": the flare is in the colour channels";
    }
    // A chosen compression overrides the plate's.
    const CliResult r = runCli({"postfx", dir.file("plate.1001.exr"), "-o", dir.file("piz.exr"),
                                "--exr-compression", "piz"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Imf::InputFile(dir.file("piz.exr").c_str()).header().compression(),
              Imf::PIZ_COMPRESSION);
}

TEST(ShotCli, AnExrsExtraChannelsCountInTheMemoryBudget) {
    // 512x512 with 64 float channels past RGBA: 64 MiB kept for the write. Under a 200 MiB
    // budget apply's own ~175 MiB fits, with the channels it does not: refused from the header.
    TempDir dir;
    const int w = 512, h = 512;
    std::vector<float> zeros(std::size_t(w * h), 0.f);
    Imf::Header header(w, h);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 68; ++c) {
        const std::string name =
            c < 4 ? std::string(1, "RGBA"[c]) : std::string("c").append(std::to_string(c));
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float),
                                   sizeof(float) * w));
    }
    {
        Imf::OutputFile file(dir.file("wide.exr").c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(h);
    }
    const CliResult r = runCli({"--max-memory", "200M", "apply", dir.file("wide.exr"), "-o",
                                dir.file("out.exr"), "--light", "9,9"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("over the memory budget"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.exr")));
    EXPECT_EQ(runCli({"--max-memory", "300M", "apply", dir.file("wide.exr"), "-o",
                      dir.file("out.exr"), "--light", "9,9"})
                  .exitCode,
              0);
}

// A plate compressed lossily (DWAA) gives its compression to the output, but the added passes
// are the values the layer files hold: the output is written losslessly (ZIP) unless
// --exr-compression names a compression.
TEST(ShotCli, LayersInOutputAreLosslessOverALossyPlate) {
    TempDir in, out;
    writeShot(in, 1);
    auto plate = readImage(in.file("in.0001.exr"));
    ASSERT_TRUE(plate);
    WriteOptions dwaa;
    dwaa.encode.exrCompression = "dwaa";
    ASSERT_TRUE(writeImage(in.file("dwaa.exr"), plate->image, dwaa));
    const CliResult r =
        runCli({"apply", in.file("dwaa.exr"), "-o", out.file("comp.exr"), "--light", "100.5,45.5",
                "--layers", out.file("layers"), "--layers-in-output"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto comp = readImage(out.file("comp.exr"));
    auto flare = readImage(out.file("layers/flare.exr"));
    ASSERT_TRUE(comp && flare);
    for (int c = 0; c < 3; ++c) {
        auto plane = channelByName(*comp, std::string("flare.") + "RGB"[c], "comp");
        ASSERT_TRUE(plane) << plane.error().message;
        for (std::size_t i = 0; i < plane->size(); ++i)
            ASSERT_EQ((*plane)[i], flare->image.data()[4 * i + std::size_t(c)]) << c << " " << i;
    }
    Imf::InputFile file(out.file("comp.exr").c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
}

TEST(ShotCli, LayersInOutputAreTheLayerFilesAsChannelsOfEachFrame) {
    TempDir in, out;
    writeShot(in, 2);
    CliResult r =
        runCli({"apply", in.file("in.####.exr"), "-o", out.file("comp.####.exr"), "--light",
                "100.5,45.5", "--layers", out.file("layers"), "--layers-in-output"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* frame : {"0001", "0002"}) {
        auto comp = readImage(out.file(std::string("comp.") + frame + ".exr"));
        ASSERT_TRUE(comp) << comp.error().message;
        int layers = 0;
        for (const char* name : {"flare", "glow", "halo", "ghosts", "streaks", "starburst"}) {
            auto file = readImage(out.file("layers/" + std::string(name) + "." + frame + ".exr"));
            if (!file) continue;  // a pass the preset does not have
            ++layers;
            for (int c = 0; c < 3; ++c) {
                const std::string channel = std::string(name) + "." + "RGB"[c];
                auto plane = channelByName(*comp, channel, "comp");
                ASSERT_TRUE(plane) << plane.error().message;
                for (std::size_t i = 0; i < plane->size(); ++i)
                    ASSERT_EQ((*plane)[i], file->image.data()[4 * i + std::size_t(c)])
                        << channel << " " << i;
            }
        }
        EXPECT_GE(layers, 3) << frame;
        // Three channels per layer and nothing else (these plates have no channel past RGBA).
        EXPECT_EQ(comp->extraChannels, 3 * layers) << frame;
    }
    // Channels need an EXR: another output is one line, no file.
    r = runCli({"postfx", in.file("in.0001.exr"), "-o", out.file("p.png"), "--layers-in-output"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--layers-in-output: the passes become channels of an EXR output"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out.file("p.png")));
}
