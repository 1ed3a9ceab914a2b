// SPDX-License-Identifier: Apache-2.0
#include <cstring>
#include <fstream>

#include "core/codecs/Codecs.h"

namespace flarekit::codec {

Format sniffFormat(const std::string& path) {
    unsigned char m[8] = {};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(m), 8);
    if (in.gcount() < 4) return Format::Other;
    // Signatures from each format's specification.
    if (std::memcmp(m, "\x89PNG\r\n\x1a\n", 8) == 0) return Format::Png;
    if (m[0] == 0xFF && m[1] == 0xD8 && m[2] == 0xFF) return Format::Jpeg;
    if ((m[0] == 'I' && m[1] == 'I' && m[2] == 42 && m[3] == 0) ||
        (m[0] == 'M' && m[1] == 'M' && m[2] == 0 && m[3] == 42))
        return Format::Tiff;  // classic TIFF (BigTIFF, 43, goes to OpenImageIO)
    if (m[0] == 0x76 && m[1] == 0x2f && m[2] == 0x31 && m[3] == 0x01) return Format::Exr;
    return Format::Other;
}

Format formatForExtension(const std::string& ext) {
    if (ext == ".png") return Format::Png;
    if (ext == ".jpg" || ext == ".jpeg") return Format::Jpeg;
    if (ext == ".tif" || ext == ".tiff") return Format::Tiff;
    if (ext == ".exr") return Format::Exr;
    return Format::Other;
}

int exifOrientation(const unsigned char* t, std::size_t size) {
    // TIFF layout (TIFF 6.0, EXIF 2.3): byte order "II" or "MM", 42, offset of IFD0; IFD0 is
    // a 16-bit count of 12-byte entries (tag, type, count, value); Orientation is tag 0x0112,
    // a SHORT.
    if (size < 8) return 1;
    const bool little = t[0] == 'I' && t[1] == 'I';
    if (!little && !(t[0] == 'M' && t[1] == 'M')) return 1;
    auto u16 = [&](std::size_t at) {
        return little ? unsigned(t[at]) | unsigned(t[at + 1]) << 8
                      : unsigned(t[at]) << 8 | unsigned(t[at + 1]);
    };
    auto u32 = [&](std::size_t at) {
        return little ? std::size_t(u16(at)) | std::size_t(u16(at + 2)) << 16
                      : std::size_t(u16(at)) << 16 | std::size_t(u16(at + 2));
    };
    if (u16(2) != 42) return 1;
    const std::size_t ifd = u32(4);
    if (ifd > size - 2) return 1;
    const std::size_t entries = u16(ifd);
    for (std::size_t i = 0; i < entries; ++i) {
        const std::size_t e = ifd + 2 + 12 * i;
        if (e + 12 > size) return 1;
        if (u16(e) == 0x0112 && u16(e + 2) == 3) {
            const unsigned v = u16(e + 8);
            return v >= 1 && v <= 8 ? int(v) : 1;
        }
    }
    return 1;
}

}  // namespace flarekit::codec
