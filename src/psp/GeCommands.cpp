// SPDX-License-Identifier: Apache-2.0
#include "psp/GeCommands.h"

namespace flarekit::psp {

const char* geCommandName(std::uint8_t opcode) {
    switch (GeCmd(opcode)) {
        case GeCmd::Nop:
            return "NOP";
        case GeCmd::VertexAddress:
            return "VADDR";
        case GeCmd::Prim:
            return "PRIM";
        case GeCmd::End:
            return "END";
        case GeCmd::Signal:
            return "SIGNAL";
        case GeCmd::Finish:
            return "FINISH";
        case GeCmd::Base:
            return "BASE";
        case GeCmd::VertexType:
            return "VTYPE";
        case GeCmd::TextureMapEnable:
            return "TME";
        case GeCmd::AlphaBlendEnable:
            return "ABE";
        case GeCmd::ZTestEnable:
            return "ZTE";
        case GeCmd::FramebufPtr:
            return "FBP";
        case GeCmd::FramebufWidth:
            return "FBW";
        case GeCmd::ZbufPtr:
            return "ZBP";
        case GeCmd::ZbufWidth:
            return "ZBW";
        case GeCmd::TexAddr0:
            return "TBP0";
        case GeCmd::TexBufWidth0:
            return "TBW0";
        case GeCmd::ClutAddr:
            return "CBP";
        case GeCmd::ClutAddrUpper:
            return "CBPH";
        case GeCmd::TransferSrc:
            return "TRXSBP";
        case GeCmd::TransferSrcWidth:
            return "TRXSBW";
        case GeCmd::TransferDst:
            return "TRXDBP";
        case GeCmd::TransferDstWidth:
            return "TRXDBW";
        case GeCmd::TexSize0:
            return "TSIZE0";
        case GeCmd::TexFormat:
            return "TPF";
        case GeCmd::LoadClut:
            return "CLOAD";
        case GeCmd::ClutFormat:
            return "CMODE";
        case GeCmd::TexFilter:
            return "TFLT";
        case GeCmd::TexWrap:
            return "TWRAP";
        case GeCmd::TexFunc:
            return "TFUNC";
        case GeCmd::FramebufPixFormat:
            return "PSM";
        case GeCmd::Scissor1:
            return "SCISSOR1";
        case GeCmd::Scissor2:
            return "SCISSOR2";
        case GeCmd::ZTest:
            return "ZTST";
        case GeCmd::BlendMode:
            return "ALPHA";
        case GeCmd::BlendFixedA:
            return "FIXA";
        case GeCmd::BlendFixedB:
            return "FIXB";
        case GeCmd::ZWriteDisable:
            return "ZMSK";
        case GeCmd::MaskRgb:
            return "PMSKC";
        case GeCmd::MaskAlpha:
            return "PMSKA";
        case GeCmd::TransferStart:
            return "TRXKICK";
        case GeCmd::TransferSrcPos:
            return "TRXSPOS";
        case GeCmd::TransferDstPos:
            return "TRXDPOS";
        case GeCmd::TransferSize:
            return "TRXSIZE";
    }
    return "";
}

}  // namespace flarekit::psp
