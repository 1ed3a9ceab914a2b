// SPDX-License-Identifier: Apache-2.0
// Display-list execution: registers, primitives, CLUT loads, block transfers. The per-pixel
// work (texture, depth, blend, mask, write) is in GePixel.cpp.
#include "psp/Ge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "psp/GeCommands.h"

namespace flarekit::psp {

namespace {
std::string hex(std::uint32_t v, int digits) {
    char text[16];
    std::snprintf(text, sizeof text, "%0*X", digits, unsigned(v));
    return text;
}
//! An address from a 24-bit parameter and the upper byte kept in bits 16-23 of its companion.
std::uint32_t address(std::uint32_t low24, std::uint32_t upperParam) {
    return (upperParam & 0xFF0000u) << 8 | low24;
}
}  // namespace

std::string Ge::fault(const std::string& what) const {
    return "GE at 0x" + hex(m_pc, 8) + ": " + what;
}

Status Ge::run(std::uint32_t listAddress, const std::function<void(int)>& onSignal,
               std::vector<std::string>* trace) {
    // A list longer than this is a runaway (no END): 1 Mi commands.
    constexpr int kMaxCommands = 1 << 20;
    std::uint32_t pc = listAddress;
    for (int n = 0; n < kMaxCommands; ++n, pc += 4) {
        m_pc = pc;
        if (!m_memory.valid(pc, 4)) return invalidInput(fault("display list runs outside memory"));
        const std::uint32_t word = m_memory.read32(pc);
        const auto op = std::uint8_t(word >> 24);
        const std::uint32_t param = word & 0xFFFFFFu;
        if (trace) {
            const char* name = geCommandName(op);
            trace->push_back(hex(pc, 8) + "  " + hex(op, 2) + " " + hex(param, 6) + "  " +
                             (*name ? name : "?"));
        }
        if (GeCmd(op) == GeCmd::End) return Ok{};
        if (GeCmd(op) == GeCmd::Signal) {
            if (onSignal) onSignal(int(param & 0xFFFF));
            continue;
        }
        if (Status s = execute(op, param); !s) return s;
    }
    return invalidInput(fault("display list has no END within 1 Mi commands"));
}

Status Ge::execute(std::uint8_t op, std::uint32_t param) {
    switch (GeCmd(op)) {
        case GeCmd::Nop:
        case GeCmd::Finish:
            return Ok{};
        case GeCmd::Base:
            m_base = param;
            return Ok{};
        case GeCmd::VertexAddress:
            m_vertexAddress = address(param, m_base);
            return Ok{};
        case GeCmd::VertexType:
            m_vertexType = param;
            return Ok{};
        case GeCmd::Prim:
            return drawPrimitive(param);
        case GeCmd::TextureMapEnable:
            m_texture = param & 1;
            return Ok{};
        case GeCmd::AlphaBlendEnable:
            m_blend = param & 1;
            return Ok{};
        case GeCmd::ZTestEnable:
            m_depthTest = param & 1;
            return Ok{};
        case GeCmd::ZWriteDisable:
            m_depthWrite = !(param & 1);
            return Ok{};
        case GeCmd::FramebufPtr:
            m_fbAddress = param;
            return Ok{};
        case GeCmd::FramebufWidth:
            m_fbAddress = address(m_fbAddress & 0xFFFFFF, param), m_fbWidth = param & 0xFFFF;
            return Ok{};
        case GeCmd::FramebufPixFormat:
            m_fbFormat = param & 3;
            return Ok{};
        case GeCmd::ZbufPtr:
            m_zAddress = param;
            return Ok{};
        case GeCmd::ZbufWidth:
            m_zAddress = address(m_zAddress & 0xFFFFFF, param), m_zWidth = param & 0xFFFF;
            return Ok{};
        case GeCmd::TexAddr0:
            m_texAddress = param;
            return Ok{};
        case GeCmd::TexBufWidth0:
            m_texAddress = address(m_texAddress & 0xFFFFFF, param), m_texBufWidth = param & 0xFFFF;
            return Ok{};
        case GeCmd::TexSize0:
            m_texLog2W = param & 0xF, m_texLog2H = (param >> 8) & 0xF;
            return Ok{};
        case GeCmd::TexFormat:
            m_texFormat = param & 0xF;
            return Ok{};
        case GeCmd::TexFilter:
            m_bilinear = (param & 7) == 1;
            return Ok{};
        case GeCmd::TexWrap:
            m_clampS = param & 1, m_clampT = (param >> 8) & 1;
            return Ok{};
        case GeCmd::TexFunc:
            m_texFunc = param & 7, m_texAlpha = (param >> 8) & 1;
            return Ok{};
        case GeCmd::ClutAddr:
            m_clutAddress = (m_clutAddress & 0xFF000000u) | param;
            return Ok{};
        case GeCmd::ClutAddrUpper:
            m_clutAddress = address(m_clutAddress & 0xFFFFFF, param);
            return Ok{};
        case GeCmd::ClutFormat:
            m_clutFormat = param;
            return Ok{};
        case GeCmd::LoadClut: {
            // The hardware copies the palette into its CLUT buffer now: later writes to that
            // memory are not seen until the next CLOAD. It reads memory, not a host copy.
            const std::uint32_t bytes = std::min<std::uint32_t>((param & 0x3F) * 32, 1024);
            if (!m_memory.valid(m_clutAddress, bytes))
                return invalidInput(fault("CLOAD outside memory"));
            for (std::uint32_t i = 0; i < bytes; ++i) m_clut[i] = m_memory.read8(m_clutAddress + i);
            return Ok{};
        }
        case GeCmd::Scissor1:
            m_scissorX1 = int(param & 0x3FF), m_scissorY1 = int((param >> 10) & 0x3FF);
            return Ok{};
        case GeCmd::Scissor2:
            m_scissorX2 = int(param & 0x3FF), m_scissorY2 = int((param >> 10) & 0x3FF);
            return Ok{};
        case GeCmd::ZTest:
            m_depthFunc = param & 7;
            return Ok{};
        case GeCmd::BlendMode:
            m_blendSrc = param & 0xF, m_blendDst = (param >> 4) & 0xF, m_blendOp = (param >> 8) & 7;
            return Ok{};
        case GeCmd::BlendFixedA:
            m_fixA = param;
            return Ok{};
        case GeCmd::BlendFixedB:
            m_fixB = param;
            return Ok{};
        case GeCmd::MaskRgb:
            m_maskRgb = param;
            return Ok{};
        case GeCmd::MaskAlpha:
            return Ok{};  // alpha bits are stencil: colour writes keep them anyway
        case GeCmd::TransferSrc:
            m_trxSrc = param;
            return Ok{};
        case GeCmd::TransferSrcWidth:
            m_trxSrc = address(m_trxSrc & 0xFFFFFF, param), m_trxSrcWidth = param & 0xFFFF;
            return Ok{};
        case GeCmd::TransferDst:
            m_trxDst = param;
            return Ok{};
        case GeCmd::TransferDstWidth:
            m_trxDst = address(m_trxDst & 0xFFFFFF, param), m_trxDstWidth = param & 0xFFFF;
            return Ok{};
        case GeCmd::TransferSrcPos:
            m_trxSrcPos = param;
            return Ok{};
        case GeCmd::TransferDstPos:
            m_trxDstPos = param;
            return Ok{};
        case GeCmd::TransferSize:
            m_trxSize = param;
            return Ok{};
        case GeCmd::TransferStart:
            return blockTransfer(param);
        case GeCmd::End:
        case GeCmd::Signal:
            return Ok{};  // handled by run()
    }
    return invalidInput(fault("command 0x" + hex(op, 2) + " is outside the emulated subset"));
}

Status Ge::blockTransfer(std::uint32_t param) {
    const std::uint32_t bpp = (param & 1) ? 4 : 2;
    const int w = int(m_trxSize & 0x3FF) + 1, h = int((m_trxSize >> 10) & 0x3FF) + 1;
    const int sx = int(m_trxSrcPos & 0x3FF), sy = int((m_trxSrcPos >> 10) & 0x3FF);
    const int dx = int(m_trxDstPos & 0x3FF), dy = int((m_trxDstPos >> 10) & 0x3FF);
    for (int y = 0; y < h; ++y) {
        const std::uint32_t from =
            m_trxSrc + (std::uint32_t(sy + y) * m_trxSrcWidth + std::uint32_t(sx)) * bpp;
        const std::uint32_t to =
            m_trxDst + (std::uint32_t(dy + y) * m_trxDstWidth + std::uint32_t(dx)) * bpp;
        if (!m_memory.valid(from, std::uint32_t(w) * bpp) ||
            !m_memory.valid(to, std::uint32_t(w) * bpp))
            return invalidInput(fault("block transfer outside memory"));
        for (std::uint32_t i = 0; i < std::uint32_t(w) * bpp; ++i)
            m_memory.gpuWrite8(to + i, m_memory.gpuRead8(from + i));
    }
    return Ok{};
}

std::uint32_t Ge::vertexSize() const {
    // Each component is aligned to its own size, the vertex to its largest one (GE layout).
    std::uint32_t size = 0, largest = 1;
    auto add = [&](std::uint32_t bytes, std::uint32_t count) {
        size = (size + bytes - 1) / bytes * bytes + bytes * count;
        largest = std::max(largest, bytes);
    };
    const std::uint32_t tc = m_vertexType & 3;
    if (tc == 2) add(2, 2);
    if (tc == 3) add(4, 2);
    if (((m_vertexType >> 2) & 7) == 7) add(4, 1);
    add(2, 3);  // position, s16
    return (size + largest - 1) / largest * largest;
}

Status Ge::readVertex(std::uint32_t at, Vertex& v) const {
    const std::uint32_t tc = m_vertexType & 3, color = (m_vertexType >> 2) & 7,
                        pos = (m_vertexType >> 7) & 3;
    if (!(m_vertexType & kVtThrough) || pos != 2 || (tc != 0 && tc != 2 && tc != 3) ||
        (color != 0 && color != 7) || (m_vertexType & 0x1DDE60u) != 0)
        return invalidInput(fault(
            "vertex type 0x" + hex(m_vertexType, 6) +
            " is outside the subset (throughmode; s16 position; u16 or float uv; 8888 colour)"));
    if (!m_memory.valid(at, vertexSize())) return invalidInput(fault("vertex read outside memory"));
    std::uint32_t offset = 0;
    if (tc == 2) {
        v.u = m_memory.gpuRead16(at), v.v = m_memory.gpuRead16(at + 2);
        offset = 4;
    } else if (tc == 3) {
        const std::uint32_t ub = m_memory.gpuRead32(at), vb = m_memory.gpuRead32(at + 4);
        std::memcpy(&v.u, &ub, 4), std::memcpy(&v.v, &vb, 4);
        offset = 8;
    }
    if (color == 7) {
        offset = (offset + 3) / 4 * 4;
        v.color = decodePixel(m_memory.gpuRead32(at + offset), kPixel8888);
        offset += 4;
    } else {
        v.color = {255, 255, 255, 255};
    }
    offset = (offset + 1) / 2 * 2;
    v.x = std::int16_t(m_memory.gpuRead16(at + offset));
    v.y = std::int16_t(m_memory.gpuRead16(at + offset + 2));
    v.z = m_memory.gpuRead16(at + offset + 4);  // throughmode depth: unsigned 16-bit
    return Ok{};
}

Status Ge::drawPrimitive(std::uint32_t param) {
    const std::uint32_t type = (param >> 16) & 7, count = param & 0xFFFF;
    const std::uint32_t perPrim = type == kPrimSprites ? 2 : type == kPrimTriangles ? 3 : 0;
    if (perPrim == 0)
        return invalidInput(fault("primitive type " + std::to_string(type) +
                                  " is outside the subset (triangles 3, sprites 6)"));
    const std::uint32_t stride = vertexSize();
    std::vector<Vertex> v(perPrim);
    for (std::uint32_t i = 0; i + perPrim <= count; i += perPrim) {
        for (std::uint32_t k = 0; k < perPrim; ++k)
            if (Status s = readVertex(m_vertexAddress + (i + k) * stride, v[k]); !s) return s;
        Status s = perPrim == 2 ? drawSprite(v[0], v[1]) : drawTriangle(v[0], v[1], v[2]);
        if (!s) return s;
    }
    m_vertexAddress += count * stride;  // the GE leaves VADDR after the last vertex
    return Ok{};
}

Status Ge::drawSprite(const Vertex& a, const Vertex& b) {
    // Pixels [x0, x1) x [y0, y1); colour and depth of the second vertex (flat); texture
    // coordinates linear across the rectangle, taken at pixel centres.
    const int x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x), y0 = std::min(a.y, b.y),
              y1 = std::max(a.y, b.y);
    const Vertex& left = a.x <= b.x ? a : b;
    const Vertex& right = a.x <= b.x ? b : a;
    const Vertex& top = a.y <= b.y ? a : b;
    const Vertex& bottom = a.y <= b.y ? b : a;
    for (int y = std::max(y0, m_scissorY1); y < std::min(y1, m_scissorY2 + 1); ++y) {
        const float t = top.v + (bottom.v - top.v) * (float(y - y0) + 0.5f) / float(y1 - y0);
        for (int x = std::max(x0, m_scissorX1); x < std::min(x1, m_scissorX2 + 1); ++x) {
            const float s = left.u + (right.u - left.u) * (float(x - x0) + 0.5f) / float(x1 - x0);
            if (Status st = shade({x, y, b.z, b.color, s, t}); !st) return st;
        }
    }
    return Ok{};
}

Status Ge::drawTriangle(const Vertex& a, const Vertex& b, const Vertex& c) {
    // Edge functions at pixel centres with a top-left rule; gouraud colour, depth and texture
    // coordinates interpolated barycentrically, colours and depth rounded to integers.
    const double area = double(b.x - a.x) * (c.y - a.y) - double(b.y - a.y) * (c.x - a.x);
    if (area == 0) return Ok{};
    const int minX = std::max({std::min({a.x, b.x, c.x}), m_scissorX1}),
              maxX = std::min({std::max({a.x, b.x, c.x}), m_scissorX2 + 1});
    const int minY = std::max({std::min({a.y, b.y, c.y}), m_scissorY1}),
              maxY = std::min({std::max({a.y, b.y, c.y}), m_scissorY2 + 1});
    auto edge = [&](const Vertex& p, const Vertex& q, double x, double y) {
        return (double(q.x - p.x) * (y - p.y) - double(q.y - p.y) * (x - p.x)) / area;
    };
    auto topLeft = [&](const Vertex& p, const Vertex& q) {
        const int dx = q.x - p.x, dy = q.y - p.y;
        return area > 0 ? (dy < 0 || (dy == 0 && dx > 0)) : (dy > 0 || (dy == 0 && dx < 0));
    };
    const bool tlA = topLeft(b, c), tlB = topLeft(c, a), tlC = topLeft(a, b);
    for (int y = minY; y < maxY; ++y) {
        for (int x = minX; x < maxX; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double wa = edge(b, c, px, py), wb = edge(c, a, px, py), wc = edge(a, b, px, py);
            if (wa < 0 || wb < 0 || wc < 0) continue;
            if ((wa == 0 && !tlA) || (wb == 0 && !tlB) || (wc == 0 && !tlC)) continue;
            auto mix = [&](double p, double q, double r) { return wa * p + wb * q + wc * r; };
            auto round = [](double v) { return int(std::lround(v)); };
            Fragment f{x,
                       y,
                       round(mix(a.z, b.z, c.z)),
                       {round(mix(a.color.r, b.color.r, c.color.r)),
                        round(mix(a.color.g, b.color.g, c.color.g)),
                        round(mix(a.color.b, b.color.b, c.color.b)),
                        round(mix(a.color.a, b.color.a, c.color.a))},
                       float(mix(a.u, b.u, c.u)),
                       float(mix(a.v, b.v, c.v))};
            if (Status st = shade(f); !st) return st;
        }
    }
    return Ok{};
}

}  // namespace flarekit::psp
