// SPDX-License-Identifier: Apache-2.0
// The PSP GE emulation of the Burnout Dominator flare. Expected bytes come from the
// seed's description and the documented filter precision (docs/psp-burnout.md), computed here
// by a separate model of the chain, not by the emulator's code.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <functional>

#include "flarekit/ImageIO.h"
#include "flarekit/Psp.h"
#include "psp/DisplayList.h"
#include "psp/Ge.h"

using namespace flarekit;
using namespace flarekit::psp;

namespace {

constexpr int kSunX = 100, kSunY = 80;  // the mask region is then (93..106, 73..86)
constexpr int kRegionX = kSunX - 7, kRegionY = kSunY - 7;

//! A frame whose 14x14 (or 16x16 for Ridge Racer: origin sun - 8) region has `hidden(i, j)`
//! occluded; nothing else occludes.
PspFrameInput input(const std::function<bool(int, int)>& hidden, int size = 14,
                    bool naive = false) {
    PspFrameInput in;
    in.occluders.assign(std::size_t(kScreenWidth * kScreenHeight), 0);
    const int x0 = kSunX - size / 2, y0 = kSunY - size / 2;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i)
            if (hidden(i, j)) in.occluders[std::size_t((y0 + j) * kScreenWidth + x0 + i)] = 1;
    in.sunX = kSunX, in.sunY = kSunY;
    in.naive = naive;
    in.keepSteps = true;
    return in;
}

//! The chain as the seed and docs/psp-burnout.md describe it: 255 where visible, one bilinear
//! tap per destination pixel centre with 4-bit weights and a truncating / 256, 14 -> 8 -> 4
//! -> 2, then one tap at the 2x2's centre.
int expectedCoverageByte(const std::function<bool(int, int)>& hidden) {
    std::vector<int> level(14 * 14);
    for (int j = 0; j < 14; ++j)
        for (int i = 0; i < 14; ++i) level[std::size_t(j * 14 + i)] = hidden(i, j) ? 0 : 255;
    int n = 14;
    auto tap = [&](double sx, double sy) {
        const int bu = int(std::floor(sx * 256)) - 128, bv = int(std::floor(sy * 256)) - 128;
        const int fu = (bu >> 4) & 15, fv = (bv >> 4) & 15, u = bu >> 8, v = bv >> 8;
        auto at = [&](int x, int y) {
            return level[std::size_t(std::min(y, n - 1) * n + std::min(x, n - 1))];
        };
        const int top = at(u, v) * (16 - fu) + at(u + 1, v) * fu,
                  bottom = at(u, v + 1) * (16 - fu) + at(u + 1, v + 1) * fu;
        return (top * (16 - fv) + bottom * fv) / 256;
    };
    for (int m : {8, 4, 2}) {
        std::vector<int> next(std::size_t(m * m));
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i)
                next[std::size_t(j * m + i)] = tap((i + 0.5) * n / m, (j + 0.5) * n / m);
        level = next, n = m;
    }
    return tap(1.0, 1.0);
}

std::uint32_t initialClut(int i) {  // what the CPU uploads (PspFrame.cpp): warm ramp, alpha 255
    return std::uint32_t(i) | std::uint32_t(i * 230 / 255) << 8 |
           std::uint32_t(i * 180 / 255) << 16 | 0xFFu << 24;
}

const Image8& step(const PspFrameResult& r, const std::string& name) {
    for (const PspStep& s : r.steps)
        if (s.name == name) return s.image;
    ADD_FAILURE() << "no step " << name;
    static Image8 none;
    return none;
}

long long flareEnergy(const PspFrameResult& r) {
    const Image8& restored = step(r, "07-restored");
    long long e = 0;
    for (std::size_t i = 0; i < r.frame.pixels.size() && i < restored.pixels.size(); ++i)
        e += r.frame.pixels[i] - restored.pixels[i];
    return e;
}

struct Mask {
    const char* name;
    std::function<bool(int, int)> hidden;
};
const Mask kMasks[] = {
    {"all visible", [](int, int) { return false; }},
    {"all hidden", [](int, int) { return true; }},
    {"left half hidden", [](int i, int) { return i < 7; }},
    {"top half hidden", [](int, int j) { return j < 7; }},
    {"checkerboard", [](int i, int j) { return (i + j) % 2 == 1; }},
    {"one visible pixel", [](int i, int j) { return !(i == 0 && j == 0); }},
    {"one hidden pixel", [](int i, int j) { return i == 0 && j == 0; }},
    {"one visible pixel inside", [](int i, int j) { return !(i == 3 && j == 10); }},
};

}  // namespace

TEST(PspBurnout, HandComputedBytes) {
    // Worked by hand from the 4-bit weights (docs/psp-burnout.md): the corner texel weighs
    // 10/16 x 10/16 at 14 -> 8, then 1/4 at each later level, each step truncated.
    EXPECT_EQ(expectedCoverageByte([](int, int) { return false; }), 255);
    EXPECT_EQ(expectedCoverageByte([](int i, int j) { return !(i == 0 && j == 0); }),
              1);  // 99, 24, 6, 1
    EXPECT_EQ(expectedCoverageByte([](int i, int j) { return i == 0 && j == 0; }),
              253);  // 155, 230, 248, 253
}

TEST(PspBurnout, CoverageByteAndClutAreExact) {
    for (const Mask& m : kMasks) {
        auto r = runPspFrame(PspTrick::Burnout, input(m.hidden));
        ASSERT_TRUE(r.ok()) << r.error().message;
        const int expected = expectedCoverageByte(m.hidden);
        EXPECT_EQ(r->coverageByte, expected) << m.name;
        EXPECT_EQ(r->clutAlpha, expected) << m.name;
        EXPECT_TRUE(r->regionRestored) << m.name;
        for (int i = 0; i < 256; ++i) {
            EXPECT_EQ(r->clutBefore[std::size_t(i)], initialClut(i)) << m.name << " entry " << i;
            // The A byte carries the coverage; G/R (depth stripes) and B (write mask) are
            // untouched.
            EXPECT_EQ(r->clutAfter[std::size_t(i)] >> 24, std::uint32_t(expected))
                << m.name << " entry " << i;
            EXPECT_EQ(r->clutAfter[std::size_t(i)] & 0xFFFFFFu, initialClut(i) & 0xFFFFFFu)
                << m.name << " entry " << i;
        }
    }
}

TEST(PspBurnout, MoreOcclusionNeverBrightens) {
    int lastByte = 256;
    long long lastEnergy = -1;
    for (int columns = 0; columns <= 14; ++columns) {
        auto r =
            runPspFrame(PspTrick::Burnout, input([columns](int i, int) { return i < columns; }));
        ASSERT_TRUE(r.ok());
        EXPECT_LE(r->coverageByte, lastByte) << columns << " columns";
        const long long energy = flareEnergy(*r);
        if (lastEnergy >= 0) {
            EXPECT_LE(energy, lastEnergy) << columns << " columns";
        }
        lastByte = r->coverageByte, lastEnergy = energy;
    }
    EXPECT_EQ(lastByte, 0);
}

TEST(PspBurnout, HiddenSunDrawsNoFlareAndTheNaiveEmulatorDrawsItAnyway) {
    auto hidden = runPspFrame(PspTrick::Burnout, input([](int, int) { return true; }));
    ASSERT_TRUE(hidden.ok());
    EXPECT_EQ(hidden->frame.pixels,
              step(*hidden, "07-restored").pixels);  // alpha 0: the flare adds nothing
    auto naive = runPspFrame(PspTrick::Burnout, input([](int, int) { return true; }, 14, true));
    ASSERT_TRUE(naive.ok());
    EXPECT_EQ(naive->coverageByte, 0);  // the chain itself works in the naive emulator...
    EXPECT_EQ(naive->clutAlpha, 255);   // ...but the CLUT it loads never saw the render
    EXPECT_EQ(naive->clutAfter, naive->clutBefore);
    auto visible = runPspFrame(PspTrick::Burnout, input([](int, int) { return false; }));
    ASSERT_TRUE(visible.ok());
    EXPECT_GT(flareEnergy(*naive), 0);
    EXPECT_EQ(naive->clutAfter,
              visible->clutAfter);  // the same full-alpha CLUT as a fully visible sun
    // Full flare regardless: as bright as the visible sun's (less only where the flare lies
    // over the occluder square and the sky's clamped colours differ).
    EXPECT_GT(flareEnergy(*naive), flareEnergy(*visible) * 9 / 10);
}

TEST(PspBurnout, SunOutsideTheScreenGivesNoFlare) {
    PspFrameInput in = input([](int, int) { return false; });
    in.sunX = -40;
    auto r = runPspFrame(PspTrick::Burnout, in);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r->sunInFrame);
    EXPECT_EQ(r->coverageByte, 0);
    EXPECT_EQ(r->frame.pixels, step(*r, "01-scene").pixels);
}

TEST(PspBurnout, BadInputIsAnError) {
    PspFrameInput in;
    in.occluders.assign(100, 0);
    EXPECT_FALSE(runPspFrame(PspTrick::Burnout, in).ok());
    Image8 small{320, 240, 1, std::vector<std::uint8_t>(320 * 240)};
    auto mask = occludersFromMask(small, "m.png");
    ASSERT_FALSE(mask.ok());
    EXPECT_NE(mask.error().message.find("480x272"), std::string::npos);
}

TEST(PspRidgeRacer, SumCountsVisiblePixelsAndSaturates) {
    auto count = [](const std::function<bool(int, int)>& hidden) {
        auto r = runPspFrame(PspTrick::RidgeRacer, input(hidden, 16));
        EXPECT_TRUE(r.ok());
        EXPECT_TRUE(r->regionRestored);
        return r->coverageByte;
    };
    EXPECT_EQ(count([](int, int) { return true; }), 0);
    EXPECT_EQ(count([](int i, int j) { return !(i == 5 && j == 9); }), 1);
    EXPECT_EQ(count([](int i, int) { return i < 8; }), 128);
    EXPECT_EQ(count([](int, int) { return false; }), 255);  // 256 adds of 1 clamp at 255
}

TEST(PspGe, ClutLoadCopiesAtExecution) {
    Memory memory;
    const std::uint32_t clut = kRamBase + 0x10000;
    for (int i = 0; i < 256; ++i)
        memory.write32(clut + std::uint32_t(i) * 4, 0x11111111u * std::uint32_t(i % 16));
    DisplayList list(memory, kRamBase, kRamBase + 0x20000);
    list.loadClut(clut, kPixel8888, 256);
    const std::uint32_t start = list.end();
    Ge ge(memory);
    ASSERT_TRUE(ge.run(start).ok());
    EXPECT_EQ(ge.clutBuffer()[4 * 5], 0x55);
    memory.write32(clut + 5 * 4, 0xAABBCCDDu);  // a later write is not seen until the next CLOAD
    EXPECT_EQ(ge.clutBuffer()[4 * 5], 0x55);
    ASSERT_TRUE(ge.run(start).ok());
    EXPECT_EQ(ge.clutBuffer()[4 * 5], 0xDD);
}

TEST(PspGe, PixelFormatsAndWriteMask) {
    for (std::uint32_t v = 0; v < 65536; ++v)
        ASSERT_EQ(encodePixel(decodePixel(v, kPixel565), kPixel565), v);
    // PMSKC R 0xFF, G 0x1F, B 0x00 protects bits 0-7 of a 565 pixel: the seed's 0xFF00 writes.
    EXPECT_EQ(protectedBits(0x001FFF, kPixel565), 0x00FFu);
    // The gradient CLUT entry n << 8 comes back as n in the high byte.
    for (std::uint32_t n = 0; n < 256; ++n)
        EXPECT_EQ(encodePixel(decodePixel(n << 8, kPixel565), kPixel565) >> 8, n);
}

TEST(PspGe, UnsupportedCommandIsAnErrorNotACrash) {
    Memory memory;
    memory.write32(kRamBase, 0x05000000u);  // BEZIER: outside the subset
    Ge ge(memory);
    auto s = ge.run(kRamBase);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("outside the emulated subset"), std::string::npos);
    EXPECT_FALSE(ge.run(kRamBase + kRamSize - 2).ok());  // a list running off the end of RAM
}

// `flarekit psp burnout` through the library alone: the mask read from a file gives the frame
// the in-memory run gives, byte for byte, and the steps and the trace are written beside it.
TEST(PspFrameJob, FromFilesWritesTheFrameTheStepsAndTheTrace) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("flarekit-psp-job-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const PspFrameInput in = input([](int i, int j) { return i < 5 && j < 9; });
    Image8 mask{kScreenWidth, kScreenHeight, 1, {}};
    for (std::uint8_t o : in.occluders) mask.pixels.push_back(o ? 255 : 0);
    ASSERT_TRUE(writeImage8((dir / "mask.png").string(), mask).ok());

    PspFrameJobOptions o;
    o.occluders = (dir / "mask.png").string();
    o.sunX = kSunX, o.sunY = kSunY;
    o.output = (dir / "frame.png").string();
    o.dumpDir = (dir / "steps").string();
    o.traceFile = (dir / "trace.txt").string();
    auto job = runPspFrameJob(PspTrick::Burnout, o);
    ASSERT_TRUE(job.ok()) << job.error().message;
    auto direct = runPspFrame(PspTrick::Burnout, in);
    ASSERT_TRUE(direct.ok());
    EXPECT_EQ(job->coverageByte, direct->coverageByte);
    auto written = readImage8(o.output);
    ASSERT_TRUE(written.ok());
    EXPECT_EQ(written->pixels, direct->frame.pixels);
    for (const PspStep& step : direct->steps)
        EXPECT_TRUE(std::filesystem::exists(dir / "steps" / (step.name + ".png"))) << step.name;
    EXPECT_GT(std::filesystem::file_size(o.traceFile), 1000u);

    o.occluders = (dir / "missing.png").string();
    auto missing = runPspFrameJob(PspTrick::Burnout, o);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("missing.png"), std::string::npos);
    std::filesystem::remove_all(dir);
}
