// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the image-read path with its size, ratio and memory checks (readImage and
// readImage8): flarekit's own PNG, JPEG, TIFF and EXR codecs, chosen by the file's first bytes,
// and the OpenImageIO module for the rest. The first byte picks the file's extension (PNG, JPEG,
// TIFF, EXR, HDR, BMP, TGA, PPM), which OpenImageIO consults; the rest is the file.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/ImageIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    if (size < 1) return 0;
    static const char* kExtensions[] = {".png", ".jpg", ".tif", ".exr",
                                        ".hdr", ".bmp", ".tga", ".ppm"};
    const std::string path = "/tmp/flarekit-fuzz-" + std::to_string(::getpid()) +
                             kExtensions[data[0] % (sizeof kExtensions / sizeof *kExtensions)];
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
    (void)flarekit::readImage(path);
    (void)flarekit::readImage8(path);
    ::unlink(path.c_str());
    return 0;
}
