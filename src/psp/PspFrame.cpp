// SPDX-License-Identifier: Apache-2.0
// The game frames as display lists (steps 1-6 of the trick as Rydgård's "The lens flare in
// Burnout" describes it) and the harness that runs them, takes the dumps at the lists' SIGNAL
// markers and reads the results out of emulated memory.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "flarekit/Psp.h"
#include "psp/DisplayList.h"
#include "psp/Ge.h"

namespace flarekit::psp {

namespace {
// Memory map. VRAM: the 8888 frame (stride 512: columns 480-511 are the unused border where
// the chain runs, as in the game), its depth buffer, the backup of the mask region, the flare
// texture's CLUT and the striped depth buffer of the CLUT render. RAM: list, vertices, flare
// texture, gradient CLUT, depth stripes.
constexpr int kStride = 512;
constexpr std::uint32_t kFrame = kVramBase;                              // 512 x 272 x 4
constexpr std::uint32_t kDepth = kFrame + kStride * kScreenHeight * 4;   // 512 x 272 x 2
constexpr std::uint32_t kBackup = kDepth + kStride * kScreenHeight * 2;  // 16 x 16 x 4
constexpr std::uint32_t kFlareClut = kBackup + 16 * 16 * 4;              // 256 x 4
constexpr std::uint32_t kClutDepth = kFlareClut + 256 * 4;               // 512 x 2
constexpr std::uint32_t kList = kRamBase;
constexpr std::uint32_t kVertices = kRamBase + 0x100000;
constexpr std::uint32_t kFlareTexture = kRamBase + 0x300000;      // 64 x 64 T8
constexpr std::uint32_t kGradientClut = kFlareTexture + 64 * 64;  // 256 x 16-bit
constexpr std::uint32_t kStripes = kGradientClut + 512;           // 512 x 16-bit

//! Burnout's mask and chain (the blog): 14x14, then 8, 4, 2 and one value over 2x2 pixels.
constexpr int kMask = 14;
//! Where the chain's levels sit in the border (x, level size): 8x8, 4x4, 2x2, then the 2x2 of
//! the final value. The coverage byte is the R byte of pixel (496, 0).
constexpr int kLevel8X = 480, kLevel4X = 488, kLevel2X = 492, kFinalX = 496;
constexpr std::uint32_t kCoverageByte = kFrame + kFinalX * 4;
//! Ridge Racer: a 16x16 mask summed into pixel (480, 0).
constexpr int kRidgeMask = 16;
constexpr std::uint32_t kRidgeSum = kFrame + 480 * 4;

//! Depths: sky and sun at 0 (the cleared far value), occluders nearer (larger, as many PSP
//! games use the range), the black mask rectangle just in front of the sky.
constexpr int kOccluderZ = 0x8000, kMaskZ = 1;
//! The CLUT render's stripes: 0 under the G/R halves, 32767 under the A/B halves; the sprite
//! at 16384 with LESS passes only on the A/B halves (the seed's "0, 32767, 0, 32767").
constexpr int kStripeLow = 0, kStripeHigh = 32767, kClutPassZ = 16384;
//! PMSKC (set bit = protected): R 0xFF, G 0x1F, B 0x00. In a 565 pixel that protects bits
//! 0-7 (rrrrr and the low ggg) and writes bits 8-15 (bbbbbggg): the effectively repeating
//! 0xFF00 write mask of the seed.
constexpr std::uint32_t kHighByteOnly = 0x001FFF;

std::uint32_t rgba(int r, int g, int b, int a = 255) {
    return std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16 |
           std::uint32_t(a) << 24;
}

//! Data the CPU puts in memory before the GE runs: the flare texture (a glow and a ring, as
//! 8-bit indices), its 32-bit CLUT (warm ramp, alpha 255), the green-blue gradient CLUT that
//! turns a byte n into the 565 value n << 8 (high byte bbbbbggg = n), and the depth stripes.
void uploadAssets(Memory& m) {
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const double r = std::hypot(x + 0.5 - 32, y + 0.5 - 32) / 32;
            double v = std::pow(std::max(0.0, 1 - r), 2.0);
            v += 0.6 * std::exp(-std::pow((r - 0.82) / 0.05, 2));
            m.write8(kFlareTexture + std::uint32_t(y * 64 + x),
                     std::uint8_t(std::lround(255 * std::min(1.0, v))));
        }
    for (int i = 0; i < 256; ++i) {
        m.write32(kFlareClut + std::uint32_t(i) * 4, rgba(i, i * 230 / 255, i * 180 / 255, 255));
        m.write16(kGradientClut + std::uint32_t(i) * 2, std::uint16_t(i << 8));
    }
    for (int i = 0; i < 512; ++i)
        m.write16(kStripes + std::uint32_t(i) * 2, std::uint16_t(i % 2 ? kStripeHigh : kStripeLow));
}

//! Step 1: sky (gouraud), the sun (a 24-gon), the occluders (one sprite per run of a row).
void drawScene(DisplayList& list, const PspFrameInput& in) {
    list.framebuffer(kFrame, kStride, kPixel8888);
    list.depthBuffer(kDepth, kStride);
    list.scissor(0, 0, kScreenWidth - 1, kScreenHeight - 1);
    list.enable(GeCmd::TextureMapEnable, false);
    list.blend(false);
    list.writeMask(0);
    list.depthTest(true, kAlways, true);
    const std::uint32_t top = rgba(40, 90, 200), bottom = rgba(250, 170, 110);
    list.triangles({{0, 0, top, 0, 0, 0},
                    {0, 0, top, kScreenWidth, 0, 0},
                    {0, 0, bottom, 0, kScreenHeight, 0},
                    {0, 0, top, kScreenWidth, 0, 0},
                    {0, 0, bottom, kScreenWidth, kScreenHeight, 0},
                    {0, 0, bottom, 0, kScreenHeight, 0}});
    std::vector<ListVertex> sun;
    constexpr int kSides = 24;
    constexpr double kRadius = 6.5;
    for (int i = 0; i < kSides; ++i) {
        const double a0 = 2 * std::numbers::pi * i / kSides,
                     a1 = 2 * std::numbers::pi * (i + 1) / kSides;
        const std::uint32_t c = rgba(255, 250, 225);
        sun.push_back({0, 0, c, in.sunX, in.sunY, 0});
        sun.push_back({0, 0, c, in.sunX + int(std::lround(kRadius * std::cos(a0))),
                       in.sunY + int(std::lround(kRadius * std::sin(a0))), 0});
        sun.push_back({0, 0, c, in.sunX + int(std::lround(kRadius * std::cos(a1))),
                       in.sunY + int(std::lround(kRadius * std::sin(a1))), 0});
    }
    list.triangles(sun);
    for (int y = 0; y < kScreenHeight; ++y) {
        for (int x = 0; x < kScreenWidth;) {
            if (!in.occluders[std::size_t(y * kScreenWidth + x)]) {
                ++x;
                continue;
            }
            int end = x;
            while (end < kScreenWidth && in.occluders[std::size_t(y * kScreenWidth + end)]) ++end;
            list.sprite(x, y, end, y + 1, 0, 0, 0, 0, rgba(22, 38, 28), kOccluderZ);
            x = end;
        }
    }
    list.signal(1);
}

//! Step 2 (both tricks): back up the region, white without depth test, black with it.
void drawMask(DisplayList& list, int rx, int ry, int size) {
    list.transfer(kFrame, kStride, rx, ry, kBackup, 16, 0, 0, size, size, true);
    list.enable(GeCmd::TextureMapEnable, false);
    list.depthTest(false, kAlways, false);
    list.sprite(rx, ry, rx + size, ry + size, 0, 0, 0, 0, rgba(255, 255, 255));
    list.depthTest(true, kLess, false);  // black lands where the stored depth is an occluder's
    list.sprite(rx, ry, rx + size, ry + size, 0, 0, 0, 0, rgba(0, 0, 0), kMaskZ);
    list.depthTest(false, kAlways, false);
    list.signal(2);
}

void restoreRegion(DisplayList& list, int rx, int ry, int size) {
    list.transfer(kBackup, 16, 0, 0, kFrame, kStride, rx, ry, size, size, true);
    list.signal(7);
}

//! Steps 3-6 of Burnout: the chain, the restore, the CLUT render, the flare.
void burnoutChainAndFlare(DisplayList& list, const PspFrameInput& in, int rx, int ry) {
    // 3. Bilinear 14 -> 8 -> 4 -> 2 -> 1 (the last value drawn over 2x2 pixels). The
    // framebuffer rows are textures of buffer width 512; u, v in texels. The scissor opens
    // onto the border.
    list.scissor(0, 0, kStride - 1, kScreenHeight - 1);
    list.textureFunction(kTexReplace);
    list.texture(kFrame + std::uint32_t(ry) * kStride * 4, kStride, 9, 4, kTex8888, true);
    list.sprite(kLevel8X, 0, kLevel8X + 8, 8, float(rx), 0, float(rx + kMask), float(kMask),
                0xFFFFFFFF);
    list.signal(3);
    list.texture(kFrame, kStride, 9, 3, kTex8888, true);
    list.sprite(kLevel4X, 0, kLevel4X + 4, 4, kLevel8X, 0, kLevel8X + 8, 8, 0xFFFFFFFF);
    list.signal(4);
    list.sprite(kLevel2X, 0, kLevel2X + 2, 2, kLevel4X, 0, kLevel4X + 4, 4, 0xFFFFFFFF);
    list.signal(5);
    list.sprite(kFinalX, 0, kFinalX + 2, 2, kLevel2X + 1, 1, kLevel2X + 1, 1,
                0xFFFFFFFF);  // the 2x2's centre
    list.signal(6);
    list.enable(GeCmd::TextureMapEnable, false);
    // 4. Restore.
    restoreRegion(list, rx, ry, kMask);
    // 5. The flare CLUT as a 512x1 565 target; the coverage byte as a 1x1 T8 texture through
    // the gradient CLUT; high bytes only (mask); A/B halves only (depth stripes).
    list.transfer(kStripes, 512, 0, 0, kClutDepth, 512, 0, 0, 512, 1, false);
    list.framebuffer(kFlareClut, 512, kPixel565);
    list.depthBuffer(kClutDepth, 512);
    list.scissor(0, 0, 511, 0);
    list.loadClut(kGradientClut, kPixel565, 256);
    list.texture(kCoverageByte, 16, 0, 0, kTexT8, false);
    list.textureFunction(kTexReplace);
    list.writeMask(kHighByteOnly);
    list.depthTest(true, kLess, false);
    list.sprite(0, 0, 512, 1, 0, 0, 1, 1, 0xFFFFFFFF, kClutPassZ);
    list.writeMask(0);
    list.depthTest(false, kAlways, false);
    list.framebuffer(kFrame, kStride, kPixel8888);
    list.depthBuffer(kDepth, kStride);
    list.scissor(0, 0, kScreenWidth - 1, kScreenHeight - 1);
    list.signal(8);
    // 6. The flare: the T8 texture through the CLUT loaded now (its alpha = coverage),
    // additive (src x alpha + dst), sprites along the line from the sun through the centre.
    list.loadClut(kFlareClut, kPixel8888, 256);
    list.texture(kFlareTexture, 64, 6, 6, kTexT8, true);
    list.textureFunction(kTexModulate);
    list.blend(true, kSrcSrcAlpha, kDstFixB, 0, 0xFFFFFF);
    struct Element {
        double along;
        int size;
        std::uint32_t tint;
    };
    const Element elements[] = {{0.0, 120, rgba(255, 240, 210)}, {0.45, 22, rgba(120, 200, 255)},
                                {0.75, 46, rgba(255, 170, 90)},  {1.15, 18, rgba(140, 255, 160)},
                                {1.45, 70, rgba(200, 140, 255)}, {1.9, 34, rgba(255, 210, 120)}};
    for (const Element& e : elements) {
        const double cx = in.sunX + (kScreenWidth / 2.0 - in.sunX) * e.along,
                     cy = in.sunY + (kScreenHeight / 2.0 - in.sunY) * e.along;
        const int x0 = int(std::lround(cx - e.size / 2.0)),
                  y0 = int(std::lround(cy - e.size / 2.0));
        list.sprite(x0, y0, x0 + e.size, y0 + e.size, 0, 0, 64, 64, e.tint);
    }
    list.blend(false);
    list.enable(GeCmd::TextureMapEnable, false);
}

//! Ridge Racer: sum the 16x16 mask into one pixel (each white pixel adds 1 through FIXA =
//! 1/255, FIXB = 1), restore, then gouraud hexagons modulated by that pixel as a 1x1 texture.
void ridgeRacerSumAndFlare(DisplayList& list, const PspFrameInput& in, int rx, int ry) {
    list.scissor(0, 0, kStride - 1, kScreenHeight - 1);
    list.sprite(480, 0, 481, 1, 0, 0, 0, 0, rgba(0, 0, 0));
    list.texture(kFrame + std::uint32_t(ry) * kStride * 4, kStride, 9, 4, kTex8888, false);
    list.textureFunction(kTexReplace);
    list.blend(true, kSrcFixA, kDstFixB, 0x010101, 0xFFFFFF);
    for (int j = 0; j < kRidgeMask; ++j)
        for (int i = 0; i < kRidgeMask; ++i)
            list.sprite(480, 0, 481, 1, float(rx + i), float(j), float(rx + i + 1), float(j + 1),
                        0xFFFFFFFF);
    list.blend(false);
    list.enable(GeCmd::TextureMapEnable, false);
    list.signal(3);
    restoreRegion(list, rx, ry, kRidgeMask);
    list.scissor(0, 0, kScreenWidth - 1, kScreenHeight - 1);
    list.texture(kRidgeSum, 16, 0, 0, kTex8888, false);
    list.textureFunction(kTexModulate);
    list.blend(true, kSrcFixA, kDstFixB, 0xFFFFFF, 0xFFFFFF);
    struct Hexagon {
        double along;
        int radius;
        std::uint32_t centre, rim;
    };
    const Hexagon hexagons[] = {{0.3, 14, rgba(160, 200, 255), rgba(40, 60, 120)},
                                {0.7, 24, rgba(255, 190, 120), rgba(90, 40, 20)},
                                {1.2, 10, rgba(170, 255, 170), rgba(30, 80, 30)},
                                {1.6, 34, rgba(210, 160, 255), rgba(50, 30, 90)}};
    for (const Hexagon& h : hexagons) {
        const int cx = int(std::lround(in.sunX + (kScreenWidth / 2.0 - in.sunX) * h.along));
        const int cy = int(std::lround(in.sunY + (kScreenHeight / 2.0 - in.sunY) * h.along));
        std::vector<ListVertex> v;
        for (int k = 0; k < 6; ++k) {
            const double a0 = std::numbers::pi / 3 * k, a1 = std::numbers::pi / 3 * (k + 1);
            v.push_back({0.5f, 0.5f, h.centre, cx, cy, 0});
            v.push_back({0.5f, 0.5f, h.rim, cx + int(std::lround(h.radius * std::cos(a0))),
                         cy + int(std::lround(h.radius * std::sin(a0))), 0});
            v.push_back({0.5f, 0.5f, h.rim, cx + int(std::lround(h.radius * std::cos(a1))),
                         cy + int(std::lround(h.radius * std::sin(a1))), 0});
        }
        list.triangles(v);
    }
    list.blend(false);
    list.enable(GeCmd::TextureMapEnable, false);
}

//! Reads pixels (8888) of the frame as the GE sees them, scaled by `zoom` (nearest).
Image8 framePixels(const Memory& m, int x0, int y0, int w, int h, int zoom = 1) {
    Image8 image{w * zoom, h * zoom, 3,
                 std::vector<std::uint8_t>(std::size_t(w * zoom * h * zoom * 3))};
    for (int y = 0; y < h * zoom; ++y)
        for (int x = 0; x < w * zoom; ++x) {
            const std::uint32_t p =
                m.gpuRead32(kFrame + std::uint32_t((y0 + y / zoom) * kStride + x0 + x / zoom) * 4);
            std::uint8_t* o = &image.pixels[std::size_t((y * w * zoom + x) * 3)];
            o[0] = std::uint8_t(p), o[1] = std::uint8_t(p >> 8), o[2] = std::uint8_t(p >> 16);
        }
    return image;
}

//! The flare CLUT as CLOAD reads it (plain memory).
std::array<std::uint32_t, 256> clutInMemory(const Memory& m) {
    std::array<std::uint32_t, 256> c{};
    for (int i = 0; i < 256; ++i) c[std::size_t(i)] = m.read32(kFlareClut + std::uint32_t(i) * 4);
    return c;
}

//! A CLUT as a strip: 256 entries 2 px wide; colour on top, alpha as grey below.
Image8 clutStrip(const std::array<std::uint32_t, 256>& clut) {
    constexpr int kWidth = 512, kHeight = 48;
    Image8 image{kWidth, kHeight, 3, std::vector<std::uint8_t>(std::size_t(kWidth * kHeight * 3))};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::uint32_t c = clut[std::size_t(x / 2)];
            std::uint8_t* o = &image.pixels[std::size_t((y * kWidth + x) * 3)];
            if (y < kHeight / 2)
                o[0] = std::uint8_t(c), o[1] = std::uint8_t(c >> 8), o[2] = std::uint8_t(c >> 16);
            else
                o[0] = o[1] = o[2] = std::uint8_t(c >> 24);
        }
    return image;
}
}  // namespace

Result<std::vector<std::uint8_t>> occludersFromMask(const Image8& mask, const std::string& name) {
    if (mask.width != kScreenWidth || mask.height != kScreenHeight)
        return invalidInput(name + ": occluder mask must be " + std::to_string(kScreenWidth) + "x" +
                            std::to_string(kScreenHeight) + " (the PSP screen), got " +
                            std::to_string(mask.width) + "x" + std::to_string(mask.height));
    std::vector<std::uint8_t> occluders(std::size_t(kScreenWidth * kScreenHeight));
    for (std::size_t i = 0; i < occluders.size(); ++i)
        occluders[i] = mask.pixels[i * std::size_t(mask.channels)] != 0;
    return occluders;
}

Result<PspFrameResult> runPspFrame(PspTrick trick, const PspFrameInput& in) {
    if (in.occluders.size() != std::size_t(kScreenWidth * kScreenHeight))
        return invalidInput("occluders: expected " + std::to_string(kScreenWidth * kScreenHeight) +
                            " values (480x272), got " + std::to_string(in.occluders.size()));
    if (std::abs(in.sunX) > 8192 || std::abs(in.sunY) > 8192)
        return invalidInput("sun: position (" + std::to_string(in.sunX) + ", " +
                            std::to_string(in.sunY) + ") is beyond +-8192");
    Memory memory(in.naive ? MemoryModel::SplitFramebuffers : MemoryModel::Unified);
    uploadAssets(memory);
    PspFrameResult out;
    out.sunInFrame =
        in.sunX >= 0 && in.sunX < kScreenWidth && in.sunY >= 0 && in.sunY < kScreenHeight;
    const int size = trick == PspTrick::Burnout ? kMask : kRidgeMask;
    out.maskPixels = size * size;
    // The mask region: centred on the sun, kept inside the screen near its edges.
    const int rx = std::clamp(in.sunX - size / 2, 0, kScreenWidth - size),
              ry = std::clamp(in.sunY - size / 2, 0, kScreenHeight - size);

    DisplayList list(memory, kList, kVertices);
    drawScene(list, in);
    if (out.sunInFrame) {  // a sun off screen has no mask region: no flare (docs/psp-burnout.md)
        drawMask(list, rx, ry, size);
        if (trick == PspTrick::Burnout)
            burnoutChainAndFlare(list, in, rx, ry);
        else
            ridgeRacerSumAndFlare(list, in, rx, ry);
    }
    list.signal(9);
    const std::uint32_t start = list.end();

    out.clutBefore = clutInMemory(memory);
    Image8 regionBefore;
    auto onSignal = [&](int id) {
        auto keep = [&](const std::string& name, Image8 image) {
            if (in.keepSteps) out.steps.push_back({name, std::move(image)});
        };
        switch (id) {
            case 1:
                regionBefore = framePixels(memory, rx, ry, size, size);
                keep("01-scene", framePixels(memory, 0, 0, kScreenWidth, kScreenHeight));
                break;
            case 2: {
                const Image8 mask = framePixels(memory, rx, ry, size, size);
                for (std::size_t i = 0; i < mask.pixels.size(); i += 3)
                    out.visiblePixels += mask.pixels[i] == 255;
                keep("02-mask", framePixels(memory, rx, ry, size, size, 16));
                break;
            }
            case 3:
                if (trick == PspTrick::Burnout)
                    keep("03-level-8x8", framePixels(memory, kLevel8X, 0, 8, 8, 16));
                else
                    keep("03-sum", framePixels(memory, 480, 0, 1, 1, 64));
                break;
            case 4:
                keep("04-level-4x4", framePixels(memory, kLevel4X, 0, 4, 4, 16));
                break;
            case 5:
                keep("05-level-2x2", framePixels(memory, kLevel2X, 0, 2, 2, 16));
                break;
            case 6:
                keep("06-level-1-over-2x2", framePixels(memory, kFinalX, 0, 2, 2, 16));
                break;
            case 7:
                out.regionRestored =
                    framePixels(memory, rx, ry, size, size).pixels == regionBefore.pixels;
                keep("07-restored", framePixels(memory, 0, 0, kScreenWidth, kScreenHeight));
                if (trick == PspTrick::Burnout)
                    keep("08-clut-before", clutStrip(out.clutBefore));  // step 5 is next
                break;
            case 8:
                keep("09-clut-after", clutStrip(clutInMemory(memory)));
                break;
            case 9:
                keep("10-final", framePixels(memory, 0, 0, kScreenWidth, kScreenHeight));
                break;
            default:
                break;
        }
    };
    Ge ge(memory);
    if (Status s = ge.run(start, onSignal, in.trace ? &out.trace : nullptr); !s) return s.error();

    out.clutAfter = clutInMemory(memory);
    out.frame = framePixels(memory, 0, 0, kScreenWidth, kScreenHeight);
    if (out.sunInFrame) {
        out.coverageByte = memory.gpuRead8(trick == PspTrick::Burnout ? kCoverageByte : kRidgeSum);
        if (trick == PspTrick::Burnout) out.clutAlpha = ge.clutBuffer()[3];  // entry 0's alpha byte
    }
    return out;
}

}  // namespace flarekit::psp
