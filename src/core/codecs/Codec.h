// SPDX-License-Identifier: Apache-2.0
// What every image codec of flarekit shares: the header it reports before decoding, the
// samples it decodes, the samples it encodes. PNG, JPEG, TIFF and EXR are read and written
// through their own libraries (libpng, libjpeg-turbo, libtiff, OpenEXR); every other format
// through OpenImageIO, which is loaded only when such a file is met (OiioModule.h): linking it
// costs every run about a quarter of a second of dynamic loading (263 libraries).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flarekit/Result.h"

namespace flarekit {
struct ExrExtras;
}

namespace flarekit::codec {

enum class SampleType { U8, U16, F32 };

inline std::size_t sampleBytes(SampleType t) {
    return t == SampleType::U8 ? 1 : t == SampleType::U16 ? 2 : 4;
}

//! What a file says about itself, read before any pixel memory is allocated.
struct Header {
    int width = 0;
    int height = 0;
    int channels = 0;             //!< in the file
    bool isFloat = false;         //!< half/float samples
    bool declaredLinear = false;  //!< an integer file tagged as linear light
    SampleType decodeAs = SampleType::U8;
    //! Bytes per pixel of the channels read besides the image (an EXR's past RGBA, kept for the
    //! write): part of what the memory check counts.
    double extraBytesPerPixel = 0;
    std::string format;  //!< "PNG", "JPEG", ... (the OIIO format name for the module)
};

//! Checks a header against flarekit's limits (sizes, pixels per byte, memory budget) before the
//! codec allocates pixels; an error stops the read.
using HeaderCheck = std::function<Status(const Header&)>;

//! Decoded samples: the first min(channels, 4) channels interleaved, top row first.
struct Raw {
    Header header;
    int channels = 0;     //!< kept: min(header.channels, 4)
    int orientation = 1;  //!< EXIF orientation, 1 = as stored
    std::vector<unsigned char> bytes;
    std::string warning;  //!< the decoder's first warning about a whole image, or empty

    std::size_t sampleCount() const {
        return std::size_t(header.width) * std::size_t(header.height) * std::size_t(channels);
    }
};

//! Samples to encode: `channels` interleaved values of `type`, top row first. With `half`, F32
//! means half floats to the EXR encoder (16-bit values, already converted) and floats to be
//! stored as half to OpenImageIO's writers.
struct Samples {
    int width = 0;
    int height = 0;
    int channels = 0;  //!< 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
    SampleType type = SampleType::U8;
    bool half = false;  //!< F32 input stored as half (EXR)
    bool srgb = false;  //!< integer samples are sRGB-encoded (tagged so where the format can)
    const void* data = nullptr;
    std::size_t pixelStride = 0;  //!< bytes from one pixel to the next; 0 = packed
    //! EXR: the input's header and other channels to write back (its size is this image's).
    const ExrExtras* extras = nullptr;
    bool chosenCompression = false;  //!< the EXR compression was chosen: it overrides the input's
    //! The samples' colour space (WriteOptions::colorSpace): EXR tags it; empty: untagged.
    std::string colorSpace;
    //! When set, the rows are not made yet: the encoder calls fillRows(y0, y1) before it reads
    //! rows [y0, y1), for disjoint ranges, possibly from several threads at once (the PNG
    //! encoder: so the rows are made beside libpng or zlib rather than all before them).
    std::function<void(int, int)> fillRows;
};

//! Rows the PNG codec hands libpng (or takes from it) at a time: at 1080p, 68 bands of about
//! 0.3 ms of sRGB conversion each, small enough that the first band's wait is short.
inline constexpr int kPngBandRows = 16;

struct EncodeOptions {
    //! zlib level for PNG, 0 (store) to 9 (smallest). 1 by default: on an 8-megapixel
    //! photograph level 6, libpng's and OpenImageIO's default, makes the file 10% smaller and
    //! takes 10x as long to compress (docs/formats.md has the figures).
    int pngCompression = 1;
    int jpegQuality = 98;  //!< OpenImageIO's default, kept so outputs did not change
    //! EXR compression by OpenEXR's name (see exrCompressionNames in ImageIO.h). PIZ by
    //! default: lossless, and on a photograph both faster and smaller than ZIP (an 8-megapixel
    //! mosaic of HDR photographs: 218 ms and 26.2 MB against ZIP's 652 ms and 30.0 MB).
    std::string exrCompression = "piz";
    //! zlib level of EXR's deflate-based compressions (zip, zips; dwaa and dwab's lossless
    //! part). 1 by default, not OpenEXR's 4: on three 1080p blender-data HDRIs (half, zip) the
    //! files are 3-4% larger and a whole `postfx` run takes a quarter less CPU (docs/formats.md).
    int exrZipLevel = 1;
};

}  // namespace flarekit::codec
