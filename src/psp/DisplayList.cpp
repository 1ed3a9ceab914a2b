// SPDX-License-Identifier: Apache-2.0
#include "psp/DisplayList.h"

#include <cstring>

namespace flarekit::psp {

namespace {
constexpr std::uint32_t kVertexType = kVtTexFloat | kVtColor8888 | kVtPosS16 | kVtThrough;
constexpr std::uint32_t kVertexBytes = 20;  // float u, v; 8888 colour; s16 x, y, z; padded to 4
std::uint32_t upper(std::uint32_t address) {
    return (address >> 8) & 0xFF0000u;
}
std::uint32_t low24(std::uint32_t address) {
    return address & 0xFFFFFFu;
}
}  // namespace

DisplayList::DisplayList(Memory& memory, std::uint32_t listAddress, std::uint32_t vertexAddress)
    : m_memory(memory), m_start(listAddress), m_pc(listAddress), m_vertices(vertexAddress) {
    command(GeCmd::VertexType, kVertexType);
}

void DisplayList::command(GeCmd op, std::uint32_t param) {
    m_memory.write32(m_pc, std::uint32_t(op) << 24 | (param & 0xFFFFFFu));
    m_pc += 4;
}

void DisplayList::framebuffer(std::uint32_t address, int width, int pixelFormat) {
    command(GeCmd::FramebufPtr, low24(address));
    command(GeCmd::FramebufWidth, upper(address) | std::uint32_t(width));
    command(GeCmd::FramebufPixFormat, std::uint32_t(pixelFormat));
}

void DisplayList::depthBuffer(std::uint32_t address, int width) {
    command(GeCmd::ZbufPtr, low24(address));
    command(GeCmd::ZbufWidth, upper(address) | std::uint32_t(width));
}

void DisplayList::scissor(int x1, int y1, int x2, int y2) {
    command(GeCmd::Scissor1, std::uint32_t(x1) | std::uint32_t(y1) << 10);
    command(GeCmd::Scissor2, std::uint32_t(x2) | std::uint32_t(y2) << 10);
}

void DisplayList::depthTest(bool on, int compare, bool write) {
    enable(GeCmd::ZTestEnable, on);
    command(GeCmd::ZTest, std::uint32_t(compare));
    command(GeCmd::ZWriteDisable, write ? 0 : 1);
}

void DisplayList::texture(std::uint32_t address, int bufferWidth, int log2Width, int log2Height,
                          int format, bool bilinear) {
    enable(GeCmd::TextureMapEnable, true);
    command(GeCmd::TexAddr0, low24(address));
    command(GeCmd::TexBufWidth0, upper(address) | std::uint32_t(bufferWidth));
    command(GeCmd::TexSize0, std::uint32_t(log2Width) | std::uint32_t(log2Height) << 8);
    command(GeCmd::TexFormat, std::uint32_t(format));
    command(GeCmd::TexFilter, bilinear ? 0x101 : 0);
    command(GeCmd::TexWrap, 0x101);  // clamp s and t
}

void DisplayList::textureFunction(int function) {
    command(GeCmd::TexFunc, std::uint32_t(function) | 1u << 8);
}

void DisplayList::loadClut(std::uint32_t address, int format, int entries) {
    command(GeCmd::ClutAddr, low24(address));
    command(GeCmd::ClutAddrUpper, upper(address));
    command(GeCmd::ClutFormat, std::uint32_t(format) | 0xFFu << 8);
    const int bytes = entries * (format == kPixel8888 ? 4 : 2);
    command(GeCmd::LoadClut, std::uint32_t(bytes / 32));
}

void DisplayList::blend(bool on, int source, int destination, std::uint32_t fixA,
                        std::uint32_t fixB) {
    enable(GeCmd::AlphaBlendEnable, on);
    if (!on) return;
    command(GeCmd::BlendMode, std::uint32_t(source) | std::uint32_t(destination) << 4 |
                                  std::uint32_t(kBlendAdd) << 8);
    command(GeCmd::BlendFixedA, fixA);
    command(GeCmd::BlendFixedB, fixB);
}

void DisplayList::writeMask(std::uint32_t protectRgb) {
    command(GeCmd::MaskRgb, protectRgb);
    command(GeCmd::MaskAlpha, 0);
}

void DisplayList::draw(int primType, const std::vector<ListVertex>& vertices) {
    command(GeCmd::Base, upper(m_vertices));
    command(GeCmd::VertexAddress, low24(m_vertices));
    for (const ListVertex& v : vertices) {
        std::uint32_t ub = 0, vb = 0;
        std::memcpy(&ub, &v.u, 4), std::memcpy(&vb, &v.v, 4);
        m_memory.write32(m_vertices, ub);
        m_memory.write32(m_vertices + 4, vb);
        m_memory.write32(m_vertices + 8, v.color);
        m_memory.write16(m_vertices + 12, std::uint16_t(v.x));
        m_memory.write16(m_vertices + 14, std::uint16_t(v.y));
        m_memory.write16(m_vertices + 16, std::uint16_t(v.z));
        m_vertices += kVertexBytes;
    }
    command(GeCmd::Prim, std::uint32_t(primType) << 16 | std::uint32_t(vertices.size()));
}

void DisplayList::sprite(int x0, int y0, int x1, int y1, float u0, float v0, float u1, float v1,
                         std::uint32_t color, int z) {
    draw(kPrimSprites, {{u0, v0, color, x0, y0, z}, {u1, v1, color, x1, y1, z}});
}

void DisplayList::triangles(const std::vector<ListVertex>& vertices) {
    draw(kPrimTriangles, vertices);
}

void DisplayList::transfer(std::uint32_t src, int srcWidth, int sx, int sy, std::uint32_t dst,
                           int dstWidth, int dx, int dy, int w, int h, bool bits32) {
    command(GeCmd::TransferSrc, low24(src));
    command(GeCmd::TransferSrcWidth, upper(src) | std::uint32_t(srcWidth));
    command(GeCmd::TransferDst, low24(dst));
    command(GeCmd::TransferDstWidth, upper(dst) | std::uint32_t(dstWidth));
    command(GeCmd::TransferSrcPos, std::uint32_t(sx) | std::uint32_t(sy) << 10);
    command(GeCmd::TransferDstPos, std::uint32_t(dx) | std::uint32_t(dy) << 10);
    command(GeCmd::TransferSize, std::uint32_t(w - 1) | std::uint32_t(h - 1) << 10);
    command(GeCmd::TransferStart, bits32 ? 1 : 0);
}

std::uint32_t DisplayList::end() {
    command(GeCmd::Finish, 0);
    command(GeCmd::End, 0);
    return m_start;
}

}  // namespace flarekit::psp
