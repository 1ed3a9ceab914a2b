// SPDX-License-Identifier: Apache-2.0
// The GE's per-pixel work: texture sampling (nearest, or bilinear with 4-bit sub-texel
// weights), the texture function, the depth test, blending, the colour write mask and the
// framebuffer write. Arithmetic (docs/psp-burnout.md, "The GE subset"):
//  - 5/6/4-bit channels expand by bit replication (x << 3 | x >> 2 for 5 bits) and pack by
//    truncation (x >> 3), so a 565 value survives decode + encode unchanged;
//  - bilinear: the sample point (pixel centre) in 1/256 texel, minus half a texel; the upper
//    4 bits of the fraction weigh the 2x2 texels, ((tl (16-fu) + tr fu)(16-fv) + (bl (16-fu)
//    + br fu) fv) / 256, truncated: the GE's 4-bit filter precision as PPSSPP's software
//    renderer (GPU/Software/Sampler.cpp) models it;
//  - modulate (t c + 127) / 255 and blending (s fs + d fd + 127) / 255, clamped: rounded
//    products, exact at 0 and 255 (the hardware's exact rounding is not public);
//  - the alpha bits of 5551/4444/8888 targets are the stencil buffer: colour writes keep them
//    (this subset has no stencil operations). That is the constraint of the seed: "the PSP is
//    not able to write arbitrary values into the alpha channel of a 32-bit render target".
#include <algorithm>
#include <cmath>

#include "psp/Ge.h"
#include "psp/GeCommands.h"

namespace flarekit::psp {

namespace {
int expand5(std::uint32_t v) {
    return int(v << 3 | v >> 2);
}
int expand6(std::uint32_t v) {
    return int(v << 2 | v >> 4);
}
int expand4(std::uint32_t v) {
    return int(v << 4 | v);
}
int clamp255(int v) {
    return std::clamp(v, 0, 255);
}

bool depthPasses(std::uint32_t func, int z, int stored) {
    switch (func) {
        case kNever:
            return false;
        case kAlways:
            return true;
        case kEqual:
            return z == stored;
        case kNotEqual:
            return z != stored;
        case kLess:
            return z < stored;
        case kLessEqual:
            return z <= stored;
        case kGreater:
            return z > stored;
        default:
            return z >= stored;  // kGreaterEqual
    }
}

//! Blend factor (0..255 per channel, as a colour) for the source (isSource) or destination.
Rgba8 blendFactor(std::uint32_t code, bool isSource, Rgba8 s, Rgba8 d, std::uint32_t fix) {
    switch (code) {
        case 2:
            return {s.a, s.a, s.a, s.a};  // SRCALPHA
        case 3:
            return {255 - s.a, 255 - s.a, 255 - s.a, 255 - s.a};  // INVSRCALPHA
        case 4:
            return {d.a, d.a, d.a, d.a};  // DSTALPHA
        case 5:
            return {255 - d.a, 255 - d.a, 255 - d.a, 255 - d.a};  // INVDSTALPHA
        case 10:
            return {int(fix & 0xFF), int((fix >> 8) & 0xFF), int((fix >> 16) & 0xFF), 0};
        default:
            break;
    }
    // 0/1: the other side's colour (src: DSTCOLOR, dst: SRCCOLOR) and its inverse.
    const Rgba8 o = isSource ? d : s;
    return code == 0 ? o : Rgba8{255 - o.r, 255 - o.g, 255 - o.b, 255 - o.a};
}
}  // namespace

std::uint32_t encodePixel(Rgba8 c, std::uint32_t format) {
    const auto r = std::uint32_t(c.r), g = std::uint32_t(c.g), b = std::uint32_t(c.b),
               a = std::uint32_t(c.a);
    switch (format) {
        case kPixel565:
            return r >> 3 | (g >> 2) << 5 | (b >> 3) << 11;
        case kPixel5551:
            return r >> 3 | (g >> 3) << 5 | (b >> 3) << 10 | (a >> 7) << 15;
        case kPixel4444:
            return r >> 4 | (g >> 4) << 4 | (b >> 4) << 8 | (a >> 4) << 12;
        default:
            return r | g << 8 | b << 16 | a << 24;
    }
}

Rgba8 decodePixel(std::uint32_t v, std::uint32_t format) {
    switch (format) {
        case kPixel565:
            return {expand5(v & 31), expand6((v >> 5) & 63), expand5((v >> 11) & 31), 255};
        case kPixel5551:
            return {expand5(v & 31), expand5((v >> 5) & 31), expand5((v >> 10) & 31),
                    (v >> 15) & 1 ? 255 : 0};
        case kPixel4444:
            return {expand4(v & 15), expand4((v >> 4) & 15), expand4((v >> 8) & 15),
                    expand4((v >> 12) & 15)};
        default:
            return {int(v & 0xFF), int((v >> 8) & 0xFF), int((v >> 16) & 0xFF), int(v >> 24)};
    }
}

std::uint32_t protectedBits(std::uint32_t maskRgb, std::uint32_t format) {
    // Alpha = stencil bits: always kept by colour writes (see above), whatever PMSKA says.
    const Rgba8 m{int(maskRgb & 0xFF), int((maskRgb >> 8) & 0xFF), int((maskRgb >> 16) & 0xFF),
                  0xFF};
    return encodePixel(m, format);
}

Rgba8 Ge::clutColor(unsigned index) const {
    // CMODE: format bits 0-1, shift 2-6, mask 8-15, start (x 16) 16-20.
    const std::uint32_t format = m_clutFormat & 3, shift = (m_clutFormat >> 2) & 31,
                        mask = (m_clutFormat >> 8) & 0xFF;
    const std::uint32_t start = ((m_clutFormat >> 16) & 31) << 4;
    const std::uint32_t i = ((index >> shift) & mask) | start;
    if (format == kPixel8888) {
        const std::uint32_t at = (i * 4) & 1023;
        return decodePixel(std::uint32_t(m_clut[at]) | std::uint32_t(m_clut[at + 1]) << 8 |
                               std::uint32_t(m_clut[at + 2]) << 16 |
                               std::uint32_t(m_clut[at + 3]) << 24,
                           kPixel8888);
    }
    const std::uint32_t at = (i * 2) & 1023;
    return decodePixel(std::uint32_t(m_clut[at]) | std::uint32_t(m_clut[at + 1]) << 8, format);
}

Status Ge::fetchTexel(int u, int v, Rgba8& out) const {
    const int w = 1 << m_texLog2W, h = 1 << m_texLog2H;
    u = m_clampS ? std::clamp(u, 0, w - 1) : (u & (w - 1));
    v = m_clampT ? std::clamp(v, 0, h - 1) : (v & (h - 1));
    const std::uint32_t texel = std::uint32_t(v) * m_texBufWidth + std::uint32_t(u);
    switch (m_texFormat) {
        case kTex8888: {
            const std::uint32_t at = m_texAddress + texel * 4;
            if (!m_memory.valid(at, 4)) break;
            out = decodePixel(m_memory.gpuRead32(at), kPixel8888);
            return Ok{};
        }
        case kTex565:
        case kTex5551:
        case kTex4444: {
            const std::uint32_t at = m_texAddress + texel * 2;
            if (!m_memory.valid(at, 2)) break;
            out = decodePixel(m_memory.gpuRead16(at), m_texFormat);
            return Ok{};
        }
        case kTexT8: {
            const std::uint32_t at = m_texAddress + texel;
            if (!m_memory.valid(at, 1)) break;
            out = clutColor(m_memory.gpuRead8(at));
            return Ok{};
        }
        case kTexT4: {
            const std::uint32_t at = m_texAddress + texel / 2;
            if (!m_memory.valid(at, 1)) break;
            const std::uint8_t pair = m_memory.gpuRead8(at);
            out = clutColor(texel & 1 ? pair >> 4 : pair & 15);
            return Ok{};
        }
        default:
            return invalidInput(fault("texture format " + std::to_string(m_texFormat) +
                                      " is outside the subset (565, 5551, 4444, 8888, T4, T8)"));
    }
    return invalidInput(fault("texture read outside memory"));
}

Status Ge::sampleTexture(float s, float t, Rgba8& out) const {
    if (!m_bilinear) return fetchTexel(int(std::floor(s)), int(std::floor(t)), out);
    const int baseU = int(std::floor(s * 256.f)) - 128, baseV = int(std::floor(t * 256.f)) - 128;
    const int fu = (baseU >> 4) & 15, fv = (baseV >> 4) & 15;
    const int u0 = baseU >> 8, v0 = baseV >> 8;  // arithmetic shifts: floor
    Rgba8 tl, tr, bl, br;
    for (auto [texel, du, dv] : {std::tuple{&tl, 0, 0}, std::tuple{&tr, 1, 0},
                                 std::tuple{&bl, 0, 1}, std::tuple{&br, 1, 1}})
        if (Status st = fetchTexel(u0 + du, v0 + dv, *texel); !st) return st;
    auto filter = [&](int a, int b, int c, int d) {
        return ((a * (16 - fu) + b * fu) * (16 - fv) + (c * (16 - fu) + d * fu) * fv) / 256;
    };
    out = {filter(tl.r, tr.r, bl.r, br.r), filter(tl.g, tr.g, bl.g, br.g),
           filter(tl.b, tr.b, bl.b, br.b), filter(tl.a, tr.a, bl.a, br.a)};
    return Ok{};
}

Status Ge::shade(const Fragment& f) {
    if (f.x < 0 || f.y < 0 || std::uint32_t(f.x) >= m_fbWidth)
        return Ok{};  // outside the buffer's stride
    Rgba8 c = f.color;
    if (m_texture) {
        Rgba8 t;
        if (Status s = sampleTexture(f.s, f.t, t); !s) return s;
        if (m_texFunc == kTexReplace) {
            c = {t.r, t.g, t.b, m_texAlpha ? t.a : c.a};
        } else if (m_texFunc == kTexModulate) {
            auto mul = [](int a, int b) { return (a * b + 127) / 255; };
            c = {mul(t.r, c.r), mul(t.g, c.g), mul(t.b, c.b), m_texAlpha ? mul(t.a, c.a) : c.a};
        } else {
            return invalidInput(fault("texture function " + std::to_string(m_texFunc) +
                                      " is outside the subset (modulate 0, replace 3)"));
        }
    }
    if (m_depthTest) {
        const std::uint32_t zAt =
            m_zAddress + (std::uint32_t(f.y) * m_zWidth + std::uint32_t(f.x)) * 2;
        if (!m_memory.valid(zAt, 2))
            return invalidInput(fault("depth buffer access outside memory"));
        const int z = std::clamp(f.z, 0, 65535);
        if (!depthPasses(m_depthFunc, z, m_memory.gpuRead16(zAt))) return Ok{};
        if (m_depthWrite) m_memory.gpuWrite16(zAt, std::uint16_t(z));
    }
    const std::uint32_t bytes = m_fbFormat == kPixel8888 ? 4 : 2;
    const std::uint32_t at =
        m_fbAddress + (std::uint32_t(f.y) * m_fbWidth + std::uint32_t(f.x)) * bytes;
    if (!m_memory.valid(at, bytes)) return invalidInput(fault("framebuffer write outside memory"));
    const std::uint32_t old = bytes == 4 ? m_memory.gpuRead32(at) : m_memory.gpuRead16(at);
    if (m_blend) {
        if (m_blendOp != kBlendAdd)
            return invalidInput(fault("blend equation " + std::to_string(m_blendOp) +
                                      " is outside the subset (add 0)"));
        const Rgba8 d = decodePixel(old, m_fbFormat);
        const Rgba8 fs = blendFactor(m_blendSrc, true, c, d, m_fixA),
                    fd = blendFactor(m_blendDst, false, c, d, m_fixB);
        auto mix = [](int s, int a, int dd, int b) {
            return clamp255((s * a + dd * b + 127) / 255);
        };
        c = {mix(c.r, fs.r, d.r, fd.r), mix(c.g, fs.g, d.g, fd.g), mix(c.b, fs.b, d.b, fd.b), c.a};
    }
    const std::uint32_t keep = protectedBits(m_maskRgb, m_fbFormat);
    const std::uint32_t value = (encodePixel(c, m_fbFormat) & ~keep) | (old & keep);
    if (bytes == 4)
        m_memory.gpuWrite32(at, value);
    else
        m_memory.gpuWrite16(at, std::uint16_t(value));
    return Ok{};
}

}  // namespace flarekit::psp
