// SPDX-License-Identifier: Apache-2.0
// The GE command subset the Burnout frame uses, with the hardware's opcode numbers (the PSP's
// display-list format: 8-bit command, 24-bit parameter per 32-bit word, as documented by
// PPSSPP's GeConstants.h and the PSPSDK's pspge headers).
#pragma once

#include <cstdint>

namespace flarekit::psp {

enum class GeCmd : std::uint8_t {
    Nop = 0x00,
    VertexAddress = 0x01,
    Prim = 0x04,
    End = 0x0C,
    Signal = 0x0E,
    Finish = 0x0F,
    Base = 0x10,
    VertexType = 0x12,
    TextureMapEnable = 0x1E,
    AlphaBlendEnable = 0x21,
    ZTestEnable = 0x23,
    FramebufPtr = 0x9C,
    FramebufWidth = 0x9D,
    ZbufPtr = 0x9E,
    ZbufWidth = 0x9F,
    TexAddr0 = 0xA0,
    TexBufWidth0 = 0xA8,
    ClutAddr = 0xB0,
    ClutAddrUpper = 0xB1,
    TransferSrc = 0xB2,
    TransferSrcWidth = 0xB3,
    TransferDst = 0xB4,
    TransferDstWidth = 0xB5,
    TexSize0 = 0xB8,
    TexFormat = 0xC3,
    LoadClut = 0xC4,
    ClutFormat = 0xC5,
    TexFilter = 0xC6,
    TexWrap = 0xC7,
    TexFunc = 0xC9,
    FramebufPixFormat = 0xD2,
    Scissor1 = 0xD4,
    Scissor2 = 0xD5,
    ZTest = 0xDE,
    BlendMode = 0xDF,
    BlendFixedA = 0xE0,
    BlendFixedB = 0xE1,
    ZWriteDisable = 0xE7,
    MaskRgb = 0xE8,
    MaskAlpha = 0xE9,
    TransferStart = 0xEA,
    TransferSrcPos = 0xEB,
    TransferDstPos = 0xEC,
    TransferSize = 0xEE,
};

//! The command's name for traces ("" for an opcode outside the subset).
const char* geCommandName(std::uint8_t opcode);

// Parameter values.
enum GePixelFormat { kPixel565 = 0, kPixel5551 = 1, kPixel4444 = 2, kPixel8888 = 3 };
enum GeTextureFormat {
    kTex565 = 0,
    kTex5551 = 1,
    kTex4444 = 2,
    kTex8888 = 3,
    kTexT4 = 4,
    kTexT8 = 5
};
enum GePrimType { kPrimTriangles = 3, kPrimSprites = 6 };
enum GeTexFunc { kTexModulate = 0, kTexReplace = 3 };
enum GeCompare {
    kNever = 0,
    kAlways = 1,
    kEqual = 2,
    kNotEqual = 3,
    kLess = 4,
    kLessEqual = 5,
    kGreater = 6,
    kGreaterEqual = 7
};
enum GeBlendSrc { kSrcSrcAlpha = 2, kSrcInvSrcAlpha = 3, kSrcFixA = 10 };
enum GeBlendDst { kDstSrcAlpha = 2, kDstInvSrcAlpha = 3, kDstFixB = 10 };
enum GeBlendOp { kBlendAdd = 0 };

// Vertex type bits (VERTEXTYPE): texture coordinates, colour, position formats, throughmode.
constexpr std::uint32_t kVtTexU16 = 2u << 0, kVtTexFloat = 3u << 0;
constexpr std::uint32_t kVtColor8888 = 7u << 2;
constexpr std::uint32_t kVtPosS16 = 2u << 7;
constexpr std::uint32_t kVtThrough = 1u << 23;

}  // namespace flarekit::psp
