// SPDX-License-Identifier: Apache-2.0
// Writes image files directly with OpenImageIO, bypassing flarekit's writer (which sanitises),
// so tests can make the bad inputs users will hand the tool: NaN pixels, odd channel counts,
// oversized images, truncated files.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace flarekit::test {

inline bool writeRaw(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type,
                     const void* data, int orientation = 1) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec(w, h, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (orientation != 1) spec.attribute("Orientation", orientation);  // EXIF, as phones write
    return out->open(path, spec) && out->write_image(type, data) && out->close();
}

inline bool writeRawFloat(const std::string& path, int w, int h, int channels,
                          const std::vector<float>& data) {
    return writeRaw(path, w, h, channels, OIIO::TypeDesc::FLOAT, data.data());
}

inline bool writeRawBytes(const std::string& path, int w, int h, int channels,
                          const std::vector<unsigned char>& data) {
    return writeRaw(path, w, h, channels, OIIO::TypeDesc::UINT8, data.data());
}

//! Keeps the first `keep` bytes of a file (a truncated download).
inline void truncateFile(const std::string& from, const std::string& to, std::size_t keep) {
    std::ifstream in(from, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.resize(std::min(bytes.size(), keep));
    std::ofstream(to, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

//! A file's bytes, and a file of these bytes (a patched copy).
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace flarekit::test
