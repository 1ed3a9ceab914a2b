// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the image-read path with its size, ratio and memory checks (readImage and
// readImage8): flarekit's own PNG, JPEG, TIFF and EXR codecs, chosen by the file's first bytes,
// and the OpenImageIO module for the rest. The first byte picks the file's extension (PNG, JPEG,
// TIFF, EXR, HDR, BMP, TGA, PPM), which OpenImageIO consults; the second the part asked of a
// multi-part EXR (none, a name, an index, "#N"), as --part does; the rest is the file. Seeds
// include a multi-part EXR (scanline and tiled parts), a truncated JPEG and one whose header
// claims more rows than its data holds.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/ImageIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    if (size < 2) return 0;
    static const char* kExtensions[] = {".png", ".jpg", ".tif", ".exr",
                                        ".hdr", ".bmp", ".tga", ".ppm"};
    const std::string path = "/tmp/flarekit-fuzz-" + std::to_string(::getpid()) +
                             kExtensions[data[0] % (sizeof kExtensions / sizeof *kExtensions)];
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data + 2, 1, size - 2, f);
    std::fclose(f);
    static const char* kParts[] = {"", "0", "1", "#1", "#0", "left", "right", "2"};
    (void)flarekit::readImage(path, {}, {kParts[data[1] % (sizeof kParts / sizeof *kParts)]});
    (void)flarekit::readImage8(path);
    ::unlink(path.c_str());
    return 0;
}
