// SPDX-License-Identifier: Apache-2.0
// The codecs flarekit runs itself (see Codec.h). Each read opens the file, reports the header
// to `check`, and only then allocates and decodes; each encode returns the file's bytes, which
// ImageIO commits with writeFileSafely.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/codecs/Codec.h"
#include "flarekit/Image.h"

namespace flarekit::codec {

enum class Format { Png, Jpeg, Tiff, Exr, Other };

//! The format of a file from its first bytes (not its name): a misnamed file still reads.
Format sniffFormat(const std::string& path);
//! The format an output name asks for, from its extension.
Format formatForExtension(const std::string& lowerExtension);

//! Where a PNG decode puts its rows when the caller converts them as they come, band by band
//! of kPngBandRows: rowsAt(raw, y0, y1) gives room for rows [y0, y1) (raw: the header; it may
//! wait until that room is free), decoded(y1) says rows up to y1 are in it. decoded(-1): the
//! decode failed; whatever reads the rows must have stopped when it returns. Raw::bytes stays
//! empty. Interlaced files, whose rows are final only after the seventh pass, ignore the
//! target and are decoded whole into Raw::bytes.
struct PngRowTarget {
    std::function<unsigned char*(const Raw& raw, int y0, int y1)> rowsAt;
    std::function<void(int rowEnd)> decoded;
};
Result<Raw> readPng(const std::string& path, const HeaderCheck& check,
                    const PngRowTarget* target = nullptr);
Result<Raw> readJpeg(const std::string& path, const HeaderCheck& check);
//! A JPEG held in memory (what encodeJpeg made); `name` names it in errors.
Result<Raw> decodeJpegBytes(const std::vector<unsigned char>& bytes, const std::string& name,
                            const HeaderCheck& check);
//! TIFF files libtiff can hand over as plain interleaved samples (grey or RGB, with or without
//! alpha, 8 or 16-bit integer or 32-bit float, strips or tiles); Unsupported for the rest
//! (palette, CMYK, planar, YCbCr, bit depths below 8), which ImageIO sends to OpenImageIO.
Result<Raw> readTiff(const std::string& path, const HeaderCheck& check);

//! An EXR read straight into float RGBA (no intermediate buffer), on OpenEXR's thread pool:
//! R, G, B (and A) or Y (and A) channels; Unsupported for other layouts (layers, chroma).
struct ExrRead {
    Header header;
    Image image;
    bool hasAlpha = false;
    bool allHalf = false;                     //!< every channel read was stored as half floats
    std::shared_ptr<const ExrExtras> extras;  //!< the header and the other channels
    std::size_t nonFinite = 0;                //!< NaN (0 in `image`) and infinite (+-65504) samples
};
//! `part`: a multi-part file's part to read, by name or index (empty: the first); the others
//! ride along in extras->parts. `partNames` gets every part's name ("0", "1" when unnamed).
Result<ExrRead> readExr(const std::string& path, const HeaderCheck& check,
                        const std::string& part = {},
                        std::vector<std::string>* partNames = nullptr);

Result<std::vector<unsigned char>> encodePng(const Samples& s, const EncodeOptions& options);
Result<std::vector<unsigned char>> encodeJpeg(const Samples& s, const EncodeOptions& options);
Result<std::vector<unsigned char>> encodeTiff(const Samples& s, const EncodeOptions& options);
Result<std::vector<unsigned char>> encodeExr(const Samples& s, const EncodeOptions& options);

//! OpenEXR's compression names encodeExr accepts (EncodeOptions::exrCompression).
std::vector<std::string> exrCompressionNames();

//! The message of a layout a native codec leaves to OpenImageIO; ImageIO checks for it.
inline constexpr const char* kUnsupportedLayout = "layout left to OpenImageIO";

//! The EXIF orientation (1-8) in a TIFF-structured EXIF block (as in a JPEG's APP1 segment
//! after "Exif\0\0", or a PNG's eXIf chunk); 1 when absent or malformed.
int exifOrientation(const unsigned char* tiff, std::size_t size);

}  // namespace flarekit::codec
