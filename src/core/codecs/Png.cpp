// SPDX-License-Identifier: Apache-2.0
// PNG through libpng. libpng reports errors by longjmp: every C++ object of a function that
// calls it is constructed before its setjmp, so the jump skips no destructor.
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/BandPipeline.h"
#include "core/FirstLine.h"
#include "core/Parallel.h"
#include "core/codecs/Codecs.h"

namespace flarekit::codec {

namespace {

struct PngErrors {
    std::string message;
};

void onError(png_structp png, png_const_charp message) {
    static_cast<PngErrors*>(png_get_error_ptr(png))->message = message ? message : "error";
    png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}  // benign (an unknown chunk, a bad CRC in a
                                                 // text chunk): the image still decodes

struct ReadState {
    PngErrors errors;
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~ReadState() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        if (file) std::fclose(file);
    }
};

}  // namespace

Result<Raw> readPng(const std::string& path, const HeaderCheck& check, const PngRowTarget* target) {
    ReadState st;
    Raw raw;
    std::vector<png_bytep> rows;
    Status checked = Ok{};
    st.file = std::fopen(path.c_str(), "rb");
    if (!st.file) return ioError(path + ": cannot read: " + std::strerror(errno));
    st.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &st.errors, onError, onWarning);
    if (st.png) st.info = png_create_info_struct(st.png);
    if (!st.png || !st.info) return internalError(path + ": libpng could not start");
    if (setjmp(png_jmpbuf(st.png))) {
        if (target) target->decoded(-1);  // whoever reads the rows stops before this returns
        return invalidInput(path + ": cannot decode image: " + excerpt(st.errors.message, 200));
    }
    png_init_io(st.png, st.file);
    // Decompressed size bound: libpng's own chunk limit stays; the image size is checked below.
    png_read_info(st.png, st.info);
    const int colourType = png_get_color_type(st.png, st.info);
    const int depth = png_get_bit_depth(st.png, st.info);
    // Palette and grey below 8 bits expand to 8-bit samples, a tRNS chunk to an alpha channel
    // (as OpenImageIO's reader did); 16-bit samples are swapped to the machine's byte order.
    if (colourType == PNG_COLOR_TYPE_PALETTE || depth < 8 ||
        png_get_valid(st.png, st.info, PNG_INFO_tRNS)) {
        png_set_expand(st.png);
    }
    if (depth == 16) png_set_swap(st.png);
    const bool interlaced = png_set_interlace_handling(st.png) > 1;
    png_read_update_info(st.png, st.info);

    raw.header.width = int(png_get_image_width(st.png, st.info));
    raw.header.height = int(png_get_image_height(st.png, st.info));
    raw.header.channels = png_get_channels(st.png, st.info);
    raw.header.decodeAs =
        png_get_bit_depth(st.png, st.info) == 16 ? SampleType::U16 : SampleType::U8;
    raw.header.format = "png";
    double gamma = 0;
    // A gAMA of 1.0 without an sRGB chunk declares linear samples.
    if (!png_get_valid(st.png, st.info, PNG_INFO_sRGB) && png_get_gAMA(st.png, st.info, &gamma))
        raw.header.declaredLinear = gamma > 0.99 && gamma < 1.01;
    checked = check(raw.header);
    if (!checked) return checked.error();
    raw.channels = raw.header.channels;
    const std::size_t rowBytes = png_get_rowbytes(st.png, st.info);
    rows.resize(std::size_t(raw.header.height));
    if (target && !interlaced) {
        for (int y = 0; y < raw.header.height; y += kPngBandRows) {
            const int n = std::min(kPngBandRows, raw.header.height - y);
            unsigned char* room = target->rowsAt(raw, y, y + n);
            for (int r = 0; r < n; ++r) rows[std::size_t(y + r)] = room + std::size_t(r) * rowBytes;
            png_read_rows(st.png, rows.data() + y, nullptr, png_uint_32(n));
            target->decoded(y + n);
        }
    } else {
        raw.bytes.resize(rowBytes * std::size_t(raw.header.height));
        for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = raw.bytes.data() + y * rowBytes;
        png_read_image(st.png, rows.data());
    }
    png_uint_32 exifBytes = 0;
    png_bytep exif = nullptr;
    if (png_get_eXIf_1(st.png, st.info, &exifBytes, &exif) && exif)
        raw.orientation = exifOrientation(exif, exifBytes);
    return raw;
}

namespace {

struct WriteState {
    PngErrors errors;
    std::vector<unsigned char> bytes;
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::vector<png_bytep> rows;
    char software[9] = "Software", flarekit[9] = "flarekit";
    png_text text{PNG_TEXT_COMPRESSION_NONE, software, flarekit, 8, 0, nullptr, nullptr};
    ~WriteState() {
        if (png) png_destroy_write_struct(&png, info ? &info : nullptr);
    }
};

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}
void noFlush(png_structp) {}

//! The chunks before the pixels: IHDR, the sRGB tag, the Software text. Called after the
//! caller's setjmp (libpng reports errors by longjmp).
void writeHeader(WriteState& st, const Samples& s) {
    png_set_write_fn(st.png, &st.bytes, appendBytes, noFlush);
    const int colourType = s.channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : s.channels == 2 ? PNG_COLOR_TYPE_GRAY_ALPHA
                           : s.channels == 3 ? PNG_COLOR_TYPE_RGB
                                             : PNG_COLOR_TYPE_RGB_ALPHA;
    const int depth = s.type == SampleType::U16 ? 16 : 8;
    png_set_IHDR(st.png, st.info, png_uint_32(s.width), png_uint_32(s.height), depth, colourType,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (s.srgb) png_set_sRGB_gAMA_and_cHRM(st.png, st.info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_set_text(st.png, st.info, &st.text, 1);
    png_write_info(st.png, st.info);
}

//! Levels above kLastSubFilterLevel: libpng filters (trying all five filters on every row) and
//! deflates. Everything that can longjmp, in a function whose state all lives in `st`.
bool writeRows(WriteState& st, const Samples& s, int level, BandPipeline* fill) {
    if (setjmp(png_jmpbuf(st.png))) return false;
    png_set_compression_level(st.png, level);
    png_set_filter(st.png, PNG_FILTER_TYPE_BASE, PNG_ALL_FILTERS);
    writeHeader(st, s);
    if (s.type == SampleType::U16) png_set_swap(st.png);
    for (int y = 0; y < s.height; y += kPngBandRows) {
        const int n = std::min(kPngBandRows, s.height - y);
        if (fill) fill->waitFor(y + n);
        png_write_rows(st.png, st.rows.data() + y, png_uint_32(n));
    }
    png_write_end(st.png, nullptr);
    return true;
}

//! Levels 0 to kLastSubFilterLevel: the Sub row filter alone. libpng tries all five filters on
//! every row and keeps the best, which at fast zlib levels costs more than the compression; the
//! Sub filter alone, on an 8-megapixel photograph at level 1, writes a file 2% larger in two
//! thirds of the time (514 against 776 ms; a 720p demo frame: the same size in 17 against
//! 37 ms). Levels above it are asked for small files: they keep the search.
constexpr int kLastSubFilterLevel = 3;
//! Rows deflated as one piece of the zlib stream, on one thread: at 1080p, 9 pieces for 2 cores
//! to share; a piece starts with an empty window, which costs a Sub-filtered photograph next
//! to nothing (its matches are a few bytes back).
constexpr int kDeflateBandRows = 128;

//! A band of rows, filtered and deflated as a piece of the IDAT zlib stream.
struct DeflatedBand {
    std::vector<unsigned char> bytes;
    uLong adler = 1;           //!< adler32 of the band's filtered bytes
    std::size_t rawBytes = 0;  //!< how many filtered bytes it holds
    bool ok = false;
};

//! Rows [y0, y1) with PNG's Sub filter (type 1: each byte less the byte one pixel before), as
//! the big-endian bytes PNG stores, deflated raw. Every piece but the last ends on a byte
//! boundary without a final block (Z_SYNC_FLUSH), so the pieces concatenate into one stream:
//! the way pigz splits gzip. Level 1 is zlib's run-length strategy: matches at distance 1
//! only, which is what Sub-filtered rows mostly hold (on the 8-megapixel photographic mosaic a
//! file 2% smaller than level 1's hashed matches in two thirds of the time; on three 1080p
//! blender-data photographs 1-6% smaller). zlib ignores the level under Z_RLE, so levels 2 and
//! 3 keep the hashed matches.
DeflatedBand deflateRows(const Samples& s, int y0, int y1, int level, bool last) {
    DeflatedBand band;
    const std::size_t sampleSize = sampleBytes(s.type);
    const std::size_t pixelBytes = std::size_t(s.channels) * sampleSize;
    const std::size_t rowBytes = std::size_t(s.width) * pixelBytes;
    std::vector<unsigned char> filtered(std::size_t(y1 - y0) * (rowBytes + 1));
    std::vector<unsigned char> bigEndian(sampleSize == 2 ? rowBytes : 0);
    for (int y = y0; y < y1; ++y) {
        const unsigned char* row =
            static_cast<const unsigned char*>(s.data) + std::size_t(y) * rowBytes;
        if (sampleSize == 2) {
            for (std::size_t i = 0; i < rowBytes; i += 2) {
                std::uint16_t v;
                std::memcpy(&v, row + i, 2);
                bigEndian[i] = static_cast<unsigned char>(v >> 8);
                bigEndian[i + 1] = static_cast<unsigned char>(v & 0xFF);
            }
            row = bigEndian.data();
        }
        unsigned char* out = filtered.data() + std::size_t(y - y0) * (rowBytes + 1);
        out[0] = 1;  // filter type Sub
        std::memcpy(out + 1, row, pixelBytes);
        for (std::size_t i = pixelBytes; i < rowBytes; ++i)
            out[1 + i] = static_cast<unsigned char>(row[i] - row[i - pixelBytes]);
    }
    band.rawBytes = filtered.size();
    band.adler = adler32(adler32(0, Z_NULL, 0), filtered.data(), uInt(filtered.size()));
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, level == 1 ? Z_RLE : Z_DEFAULT_STRATEGY) !=
        Z_OK)
        return band;
    // deflateBound counts a finished stream; a sync flush adds an empty stored block.
    band.bytes.resize(deflateBound(&z, uLong(filtered.size())) + 64);
    z.next_in = filtered.data();
    z.avail_in = uInt(filtered.size());
    z.next_out = band.bytes.data();
    z.avail_out = uInt(band.bytes.size());
    const int result = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
    band.ok =
        z.avail_in == 0 && (last ? result == Z_STREAM_END : result == Z_OK && z.avail_out > 0);
    band.bytes.resize(z.total_out);
    deflateEnd(&z);
    return band;
}

//! The image's IDAT stream in bands deflated in parallel, each band's rows made first where the
//! caller makes them as they are needed (s.fillRows): a zlib header, the pieces, the adler32 of
//! all the filtered bytes (combined from the pieces'). Empty when zlib failed.
std::vector<DeflatedBand> deflateImage(const Samples& s, int level) {
    const int bands = (s.height + kDeflateBandRows - 1) / kDeflateBandRows;
    std::vector<DeflatedBand> out(static_cast<std::size_t>(bands));
    parallelFor(0, bands, 1, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
            const int y0 = b * kDeflateBandRows, y1 = std::min(s.height, y0 + kDeflateBandRows);
            if (s.fillRows) s.fillRows(y0, y1);
            out[std::size_t(b)] = deflateRows(s, y0, y1, level, b + 1 == bands);
        }
    });
    uLong adler = out[0].adler;
    for (std::size_t b = 0; b < out.size(); ++b) {
        if (!out[b].ok) return {};
        if (b > 0) adler = adler32_combine(adler, out[b].adler, z_off_t(out[b].rawBytes));
    }
    // zlib header: deflate with a 32 KiB window (0x78), FLEVEL from the level, FCHECK making
    // the two bytes a multiple of 31 (RFC 1950).
    const unsigned cmf = 0x78, flevel = level < 2 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
    const unsigned flg = (flevel << 6) + 31 - ((cmf * 256 + (flevel << 6)) % 31);
    const unsigned char header[2] = {static_cast<unsigned char>(cmf),
                                     static_cast<unsigned char>(flg)};
    out.front().bytes.insert(out.front().bytes.begin(), header, header + 2);
    for (int shift = 24; shift >= 0; shift -= 8)
        out.back().bytes.push_back(static_cast<unsigned char>((adler >> shift) & 0xFF));
    return out;
}

//! The header chunks, one IDAT per band and IEND, through libpng's chunk writer. Each band's
//! bytes are let go once written, so the file and its bands are not both held whole.
bool writeChunks(WriteState& st, const Samples& s, std::vector<DeflatedBand>& bands) {
    if (setjmp(png_jmpbuf(st.png))) return false;
    writeHeader(st, s);
    static const png_byte kIdat[5] = "IDAT", kIend[5] = "IEND";
    for (DeflatedBand& band : bands) {
        png_write_chunk(st.png, kIdat, band.bytes.data(), band.bytes.size());
        band.bytes.clear();
        band.bytes.shrink_to_fit();
    }
    png_write_chunk(st.png, kIend, nullptr, 0);
    return true;
}

}  // namespace

Result<std::vector<unsigned char>> encodePng(const Samples& s, const EncodeOptions& options) {
    WriteState st;
    st.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &st.errors, onError, onWarning);
    if (st.png) st.info = png_create_info_struct(st.png);
    if (!st.png || !st.info) return internalError("libpng could not start");
    const int level = options.pngCompression;
    // An image without pixels goes to libpng, which refuses it with its own message.
    if (level <= kLastSubFilterLevel && s.width > 0 && s.height > 0) {
        std::vector<DeflatedBand> bands = deflateImage(s, level);
        if (bands.empty()) return internalError("cannot encode PNG: zlib failed");
        // The file's room up front (the bands, their chunk framing, the header chunks), so it
        // is never moved as it grows.
        std::size_t fileBytes = 4096;
        for (const DeflatedBand& band : bands) fileBytes += band.bytes.size() + 12;
        st.bytes.reserve(fileBytes);
        if (!writeChunks(st, s, bands)) return ioError("cannot encode PNG: " + st.errors.message);
        return std::move(st.bytes);
    }
    st.rows.resize(std::size_t(s.height));
    const std::size_t rowBytes =
        std::size_t(s.width) * std::size_t(s.channels) * sampleBytes(s.type);
    for (std::size_t y = 0; y < st.rows.size(); ++y) {
        st.rows[y] =
            const_cast<png_bytep>(static_cast<const unsigned char*>(s.data) + y * rowBytes);
    }
    // The rows made band by band beside libpng, each before it reads them.
    std::optional<BandPipeline> fill;
    if (s.fillRows) fill.emplace(s.height, kPngBandRows, s.fillRows, true);
    if (!writeRows(st, s, level, fill ? &*fill : nullptr))
        return ioError("cannot encode PNG: " + st.errors.message);
    return std::move(st.bytes);
}

}  // namespace flarekit::codec
