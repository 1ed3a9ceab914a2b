// SPDX-License-Identifier: Apache-2.0
// Writes a GE display list and its vertices into emulated memory, one helper per thing the
// game's list sets up (framebuffer, texture, CLUT load, sprite, transfer...). The words are
// the hardware's: 8-bit command, 24-bit parameter.
#pragma once

#include <cstdint>
#include <vector>

#include "psp/GeCommands.h"
#include "psp/Memory.h"

namespace flarekit::psp {

struct ListVertex {
    float u = 0, v = 0;
    std::uint32_t color = 0xFFFFFFFF;  //!< 8888, R in the low byte
    int x = 0, y = 0, z = 0;
};

class DisplayList {
  public:
    //! Commands from `listAddress` on, vertices from `vertexAddress` on (both in RAM).
    DisplayList(Memory& memory, std::uint32_t listAddress, std::uint32_t vertexAddress);

    void command(GeCmd op, std::uint32_t param);
    void enable(GeCmd flag, bool on) { command(flag, on ? 1 : 0); }
    void framebuffer(std::uint32_t address, int width, int pixelFormat);
    void depthBuffer(std::uint32_t address, int width);
    void scissor(int x1, int y1, int x2, int y2);  //!< inclusive corners
    void depthTest(bool on, int compare, bool write);
    void texture(std::uint32_t address, int bufferWidth, int log2Width, int log2Height, int format,
                 bool bilinear);
    //! TFUNC (modulate or replace, texture alpha used), clamp on both axes.
    void textureFunction(int function);
    //! CBP/CBPH, CMODE (format, mask 0xFF) and CLOAD of `entries` colours.
    void loadClut(std::uint32_t address, int format, int entries);
    void blend(bool on, int source = kSrcSrcAlpha, int destination = kDstInvSrcAlpha,
               std::uint32_t fixA = 0, std::uint32_t fixB = 0);
    void writeMask(std::uint32_t protectRgb);
    void sprite(int x0, int y0, int x1, int y1, float u0, float v0, float u1, float v1,
                std::uint32_t color, int z = 0);
    void triangles(const std::vector<ListVertex>& vertices);
    //! Block transfer of a w x h rectangle, 32-bit or 16-bit pixels.
    void transfer(std::uint32_t src, int srcWidth, int sx, int sy, std::uint32_t dst, int dstWidth,
                  int dx, int dy, int w, int h, bool bits32);
    void signal(int id) { command(GeCmd::Signal, std::uint32_t(id)); }
    //! Appends FINISH and END; returns the list's address.
    std::uint32_t end();

  private:
    void draw(int primType, const std::vector<ListVertex>& vertices);
    Memory& m_memory;
    std::uint32_t m_start, m_pc, m_vertices;
};

}  // namespace flarekit::psp
