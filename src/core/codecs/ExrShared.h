// SPDX-License-Identifier: Apache-2.0
// What the EXR reader (Exr.cpp) and writer (ExrWrite.cpp) share.
#pragma once

#include <ImfChannelList.h>
#include <ImfThreading.h>

#include <algorithm>
#include <cstddef>
#include <mutex>
#include <thread>

namespace flarekit::codec {

//! Bytes of one sample of channel c: 2 for half, 4 for float and uint.
inline std::size_t sampleBytes(const Imf::Channel& c) {
    return c.type == Imf::HALF ? 2 : 4;
}

//! OpenEXR decodes and encodes line blocks in parallel when its global pool has threads; one
//! per core, as OpenImageIO sets it.
inline void startThreadPool() {
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
    });
}

}  // namespace flarekit::codec
