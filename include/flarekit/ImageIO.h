// SPDX-License-Identifier: Apache-2.0
// Image files: EXR, PNG, JPEG and TIFF through their own libraries, every other format
// OpenImageIO reads or writes through its module (loaded on first use).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"

namespace flarekit {

//! What an EXR input holds beyond RGBA (its other channels, header attributes such as timeCode
//! and camera data, data and display windows, compression, pixel type), kept by readImage so
//! that writing the result to an EXR gives it back. Opaque outside the codecs.
struct ExrExtras;

struct LoadedImage {
    Image image;                //!< linear float RGBA
    int fileChannels = 0;       //!< channels in the file (1 grey, 2 grey+alpha, 3, 4, ...)
    bool hasAlpha = false;      //!< the file had an alpha channel
    bool wasFloat = false;      //!< half/float file, kept linear; integer files are sRGB-decoded
    std::size_t nonFinite = 0;  //!< NaN (read as 0) and infinities (as +-65504)
    int droppedChannels = 0;    //!< channels past the 4th, not kept
    bool halfExact = false;     //!< every value came from a half-float channel (an EXR's)
    std::shared_ptr<const ExrExtras> exrExtras;  //!< an EXR's other channels and header
    int extraChannels = 0;  //!< how many channels exrExtras carries (kept, not dropped)
    //! A multi-part EXR's parts by name ("0", "1" for unnamed ones), in the file's order; the
    //! ones not read ride in exrExtras to an EXR output unchanged. Empty for any other file.
    std::vector<std::string> exrParts;
    //! The decoder's warning about a file it still read whole (a corrupt marker JPEG skips), one
    //! line; empty when it had none. Jobs pass it on as a warning.
    std::string decoderWarning;
};

//! How to read a file beyond its memory.
struct ReadOptions {
    //! A multi-part EXR's part to read (stereo views, a compositor's layers): its name or its
    //! index. Empty: the first. Given for a file that has no such part: an error listing them.
    std::string part;
};

//! What the job reading an image will need, per pixel of the image and in all, so that its peak
//! is checked against the memory budget (flarekit/Limits.h) from the header, before any pixel
//! is decoded. The default is the read itself: the decoded RGBA floats plus the decode buffer.
struct JobMemory {
    double bytesPerPixel = 32;
    double fixedBytes = 0;
    std::string detail;  //!< how the estimate is made, for the message ("apply: ...")
};

//! A channel of what `loaded` read by its name in the file: R, G, B and A from the image,
//! any other an EXR carried (exrExtras: "Z", "depth.Z", "fg.A") converted to floats, row by
//! row. An error names the file's channels when there is none of that name.
Result<std::vector<float>> channelByName(const LoadedImage& loaded, const std::string& name,
                                         const std::string& source);

//! Reads any file flarekit's codecs or OpenImageIO know, by its first bytes. Sizes, the
//! pixels-per-byte ratio and the job's memory are checked before pixels are allocated.
Result<LoadedImage> readImage(const std::string& path, const JobMemory& job = {},
                              const ReadOptions& options = {});

enum class SampleFormat { Auto, U8, U16, Half, Float };
//! The formats' names (`--depth`), in SampleFormat's order.
inline constexpr std::string_view kSampleFormatNames[] = {"auto", "8", "16", "half", "float"};

//! How a file is compressed. Each write carries its own (WriteOptions::encode), so two jobs in
//! one process may write with different settings.
struct EncodeSettings {
    //! zlib level of a PNG, 0 (store) to 9 (smallest); 1: fast (docs/formats.md has the size
    //! trade-off).
    int pngCompression = 1;
    //! OpenEXR compression: none, rle, zips, zip, piz (lossless, fastest and smallest on
    //! photographs), pxr24, b44, b44a, dwaa, dwab (the last five lossy). Empty: the EXR input's
    //! own when its extras ride along, else piz. A name given overrides the input's.
    std::string exrCompression;
    //! zlib level of the EXR compressions built on deflate (zip, zips, and the lossless part of
    //! dwaa and dwab), 0 (store) to 9 (smallest); 1, where OpenEXR's own default is 4.
    int exrZipLevel = 1;
};

//! The two zlib levels, for checkEncodeSettings and the CLI's --png-compression and
//! --exr-zip-level (zlib's own levels: 0 stores, 9 is its smallest).
inline constexpr Param<EncodeSettings> kEncodeParams[] = {
    param<&EncodeSettings::pngCompression>(
        "png_compression", 0, 9, "",
        "zlib level of the PNGs written, 0 (none) to 9 (smallest). Default 1 (zlib's run-length "
        "strategy, the fastest): on an 8-megapixel photograph, 6 (libpng's default) writes a "
        "file 9% smaller taking 20x as long to compress"),
    param<&EncodeSettings::exrZipLevel>(
        "exr_zip_level", 0, 9, "",
        "zlib level of zip and zips EXRs written (and of dwaa/dwab's lossless part), 0 (none) "
        "to 9 (smallest). Default 1, ISA-L's fastest deflate: on 1080p HDR photographs level 2 "
        "(libdeflate) writes files 7-8% smaller (14% on a smooth sky) for 1.7x a postfx run's "
        "CPU; OpenEXR's default 4 is under 1% smaller again"),
};

//! Levels as kEncodeParams and a known compression name; otherwise one line naming the field.
Status checkEncodeSettings(const EncodeSettings& settings);

struct WriteOptions {
    SampleFormat format =
        SampleFormat::Auto;  //!< Auto: .exr half, .hdr float, .tif 16-bit, else 8-bit
    bool alpha = false;      //!< write RGBA (ignored by formats without alpha)
    //! Integer formats: sRGB-encode the linear values (true), or quantise them as they are
    //! (false: values an OCIO output transform has already encoded; no sRGB tag is written).
    bool srgbEncode = true;
    //! An EXR output gets the input's other channels, attributes, windows, compression (unless
    //! encode.exrCompression names one) and, with format Auto, its pixel type. Ignored by other
    //! formats and when the image is not the input's size.
    std::shared_ptr<const ExrExtras> exrExtras;
    //! The colour space the values are in, when it is not flarekit's scene-linear Rec.709 (an
    //! OCIO output transform's): an EXR is tagged with it as `oiio:ColorSpace` and, for the
    //! spaces whose primaries are known (ACEScg, ACES2065-1, Rec.709 and sRGB), with the
    //! matching `chromaticities`. Empty: untagged.
    std::string colorSpace;
    EncodeSettings encode;  //!< compression
};

//! The sample format writeImage will use for `path` (Auto resolved from the extension).
SampleFormat outputSampleFormat(const std::string& path,
                                SampleFormat requested = SampleFormat::Auto);
inline bool isFloatFormat(SampleFormat f) {
    return f == SampleFormat::Half || f == SampleFormat::Float;
}
//! Whether `path`'s format holds `requested` samples: PNG 8 and 16 bits, JPEG 8, TIFF every
//! depth, EXR half and float, Radiance HDR float (and half, written as its float), the other
//! formats 8. One line naming the file and the depths it holds otherwise (`option`, as "--depth",
//! named in it when given); writeImage refuses such a write rather than let the writer change
//! the depth, and jobs check before any work.
Status checkSampleFormatFits(const std::string& path, SampleFormat requested,
                             const std::string& option = "");

//! Writes atomically: to a temporary file beside `path`, renamed over it on success.
//! Integer formats are sRGB-encoded; float formats are written linear.
Status writeImage(const std::string& path, const Image& image, const WriteOptions& options = {});

//! Reads an 8-bit file exactly (no colour conversion); fails on other bit depths.
Result<Image8> readImage8(const std::string& path, const JobMemory& job = {4, 0, {}});
//! Writes an 8-bit image exactly (no colour conversion), atomically.
Status writeImage8(const std::string& path, const Image8& image, const EncodeSettings& encode = {});

//! The names EncodeSettings::exrCompression accepts, in OpenEXR's order.
std::vector<std::string> exrCompressionNames();

//! Fails with InvalidInput when the directory `path` would be written into does not exist.
Status checkOutputPath(const std::string& path);

}  // namespace flarekit
