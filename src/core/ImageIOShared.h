// SPDX-License-Identifier: Apache-2.0
// What reading and writing image files share (ImageIO.cpp, ImageWrite.cpp): the OpenImageIO
// module on demand, lower-case extensions and chunked loops over pixels.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "core/FirstLine.h"
#include "core/Parallel.h"
#include "core/codecs/OiioModule.h"
#include "flarekit/Result.h"

namespace flarekit::imageio {

inline std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

//! The OpenImageIO module, or null with `error` saying that `what` needs it.
inline const codec::OiioModule* moduleFor(const std::string& what, Error* error) {
    std::string why;
    const codec::OiioModule* m = codec::oiioModule(&why);
    if (!m && error) {
        *error = internalError(what +
                               " needs flarekit's OpenImageIO module, which could not be "
                               "loaded: " +
                               excerpt(why, 300));
    }
    return m;
}

//! fn(i0, i1) over [0, count) in chunks spread over the cores.
template <typename Fn>
void forEachChunk(std::size_t count, Fn fn) {
    constexpr std::size_t kChunk = 1 << 15;
    parallelFor(0, int((count + kChunk - 1) / kChunk), 1, [&](int c0, int c1) {
        fn(std::size_t(c0) * kChunk, std::min(count, std::size_t(c1) * kChunk));
    });
}

}  // namespace flarekit::imageio
