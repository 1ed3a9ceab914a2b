// SPDX-License-Identifier: Apache-2.0
// A software PSP Graphics Engine, the subset the Burnout Dominator lens flare needs:
// display lists of GE commands executed in order; throughmode sprites and triangles with flat
// or gouraud colour and texture coordinates; 565/5551/4444/8888 framebuffers with a stride;
// a 16-bit depth buffer; 8888/565 and indexed T4/T8 textures through a CLUT loaded from memory
// when CLOAD executes; nearest and bilinear filtering; modulate/replace; clamp/wrap; alpha
// blending; per-bit colour write masks; block transfers. Every arithmetic choice is written
// down in docs/psp-burnout.md ("The GE subset").
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flarekit/Result.h"
#include "psp/Memory.h"

namespace flarekit::psp {

struct Rgba8 {
    int r = 0, g = 0, b = 0, a = 0;
};

class Ge {
  public:
    explicit Ge(Memory& memory) : m_memory(memory) {}

    //! Executes the display list at `address` until END. SIGNAL n calls onSignal(n) (the hosts'
    //! hook for dumping the steps). `trace`, when given, receives one line per command.
    Status run(std::uint32_t address, const std::function<void(int)>& onSignal = {},
               std::vector<std::string>* trace = nullptr);

    //! The CLUT buffer inside the GE (1 KiB), as the last CLOAD left it.
    const std::array<std::uint8_t, 1024>& clutBuffer() const { return m_clut; }

  private:
    struct Vertex {
        float u = 0, v = 0;
        Rgba8 color;
        int x = 0, y = 0, z = 0;
    };
    struct Fragment {
        int x, y, z;
        Rgba8 color;
        float s, t;  //!< texture coordinates in texels (throughmode)
    };

    Status execute(std::uint8_t op, std::uint32_t param);
    Status drawPrimitive(std::uint32_t param);
    Status readVertex(std::uint32_t address, Vertex& v) const;
    std::uint32_t vertexSize() const;
    Status drawSprite(const Vertex& a, const Vertex& b);
    Status drawTriangle(const Vertex& a, const Vertex& b, const Vertex& c);
    Status shade(const Fragment& f);
    Status sampleTexture(float s, float t, Rgba8& out) const;
    Status fetchTexel(int u, int v, Rgba8& out) const;
    Rgba8 clutColor(unsigned index) const;
    Status blockTransfer(std::uint32_t param);
    std::string fault(const std::string& what) const;

    Memory& m_memory;
    std::array<std::uint8_t, 1024> m_clut{};
    std::uint32_t m_pc = 0;  //!< address of the command being executed (for errors and traces)

    // Registers (names as in GeCommands.h).
    std::uint32_t m_base = 0, m_vertexAddress = 0, m_vertexType = 0;
    bool m_texture = false, m_blend = false, m_depthTest = false, m_depthWrite = true;
    std::uint32_t m_fbAddress = 0, m_fbWidth = 0, m_fbFormat = 3;
    std::uint32_t m_zAddress = 0, m_zWidth = 0;
    std::uint32_t m_texAddress = 0, m_texBufWidth = 0, m_texLog2W = 0, m_texLog2H = 0,
                  m_texFormat = 3;
    std::uint32_t m_clutAddress = 0, m_clutFormat = 0;
    bool m_bilinear = false, m_clampS = false, m_clampT = false;
    std::uint32_t m_texFunc = 0;
    bool m_texAlpha = false;  //!< TFUNC's TCC bit: the texture's alpha takes part
    int m_scissorX1 = 0, m_scissorY1 = 0, m_scissorX2 = 1023, m_scissorY2 = 1023;
    std::uint32_t m_depthFunc = 1;
    std::uint32_t m_blendSrc = 2, m_blendDst = 3, m_blendOp = 0, m_fixA = 0, m_fixB = 0;
    std::uint32_t m_maskRgb = 0;
    std::uint32_t m_trxSrc = 0, m_trxSrcWidth = 0, m_trxDst = 0, m_trxDstWidth = 0;
    std::uint32_t m_trxSrcPos = 0, m_trxDstPos = 0, m_trxSize = 0;
};

// Pixel formats, as the GE packs them (little-endian; R in the low bits).
std::uint32_t encodePixel(Rgba8 c, std::uint32_t format);
Rgba8 decodePixel(std::uint32_t bits, std::uint32_t format);
//! The colour write mask PMSKC (set bit = bit protected, kept from the framebuffer) converted
//! to `format`'s bits, the same truncation as the colour, plus the alpha (stencil) bits, which
//! colour writes always keep (so PMSKA has nothing left to protect).
std::uint32_t protectedBits(std::uint32_t maskRgb, std::uint32_t format);

}  // namespace flarekit::psp
