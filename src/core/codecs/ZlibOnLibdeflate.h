// SPDX-License-Identifier: Apache-2.0
// zlib's one-shot calls answered by libdeflate and ISA-L (ZlibOnLibdeflate.cpp): how many it has
// answered (how a test tells that OpenEXR's ZIP chunks went through it), and a switch back to
// zlib for the benchmarks.
#pragma once

namespace flarekit::codec {

struct ZlibCalls {
    unsigned long compressed = 0;        //!< successful compress/compress2 calls
    unsigned long expanded = 0;          //!< successful uncompress calls
    unsigned long compressedByIsal = 0;  //!< of `compressed`, those ISA-L deflated (level 1)
};
ZlibCalls zlibCallsAnsweredByLibdeflate();

//! Hands the calls back to zlib itself (true) or to libdeflate (false, the default): for the
//! benchmarks that compare the two in one process.
void answerZlibCallsWithZlib(bool zlib);

}  // namespace flarekit::codec
