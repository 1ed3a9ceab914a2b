// PNG through libpng. libpng reports errors by longjmp: every C++ object of a function that
// calls it is constructed before its setjmp, so the jump skips no destructor.
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "core/FirstLine.h"
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

Result<Raw> readPng(const std::string& path, const HeaderCheck& check,
                    const RowsDecoded& rowsDecoded) {
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
        if (rowsDecoded) rowsDecoded(raw, -1);  // stop reading raw's rows: it goes with this
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
    raw.bytes.resize(rowBytes * std::size_t(raw.header.height));
    rows.resize(std::size_t(raw.header.height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = raw.bytes.data() + y * rowBytes;
    if (interlaced || !rowsDecoded) {
        png_read_image(st.png, rows.data());
        if (rowsDecoded) rowsDecoded(raw, raw.header.height);
    } else {
        for (int y = 0; y < raw.header.height; y += kPngBandRows) {
            const int n = std::min(kPngBandRows, raw.header.height - y);
            png_read_rows(st.png, rows.data() + y, nullptr, png_uint_32(n));
            rowsDecoded(raw, y + n);
        }
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

//! Everything that can longjmp, in a function whose state all lives in `st`.
bool writeRows(WriteState& st, const Samples& s, int level) {
    if (setjmp(png_jmpbuf(st.png))) return false;
    png_set_write_fn(st.png, &st.bytes, appendBytes, noFlush);
    const int colourType = s.channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : s.channels == 2 ? PNG_COLOR_TYPE_GRAY_ALPHA
                           : s.channels == 3 ? PNG_COLOR_TYPE_RGB
                                             : PNG_COLOR_TYPE_RGB_ALPHA;
    const int depth = s.type == SampleType::U16 ? 16 : 8;
    png_set_IHDR(st.png, st.info, png_uint_32(s.width), png_uint_32(s.height), depth, colourType,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(st.png, level);
    // Row filters: libpng tries all five on every row and keeps the best, which at fast zlib
    // levels costs more than the compression. The Sub filter alone, on an 8-megapixel
    // photograph at level 1, writes a file 2% larger in two thirds of the time (514 against
    // 776 ms; a 720p demo frame: the same size in 17 against 37 ms). Levels above 3 are asked
    // for small files: they keep the search.
    png_set_filter(st.png, PNG_FILTER_TYPE_BASE, level <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    // Level 1 (the default) is zlib's run-length strategy: matches at distance 1 only, which is
    // what Sub-filtered image rows mostly hold. On the 8-megapixel photographic mosaic it wrote
    // a file 2% smaller than level 1's hashed matches in two thirds of the time (101 against
    // 152 ms, bench_io); on three 1080p blender-data photographs, 1-6% smaller. zlib ignores
    // the level under Z_RLE, so levels 2 and 3 keep the hashed matches for whoever wants them.
    if (level == 1) png_set_compression_strategy(st.png, Z_RLE);
    if (s.srgb) png_set_sRGB_gAMA_and_cHRM(st.png, st.info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_set_text(st.png, st.info, &st.text, 1);
    png_write_info(st.png, st.info);
    if (depth == 16) png_set_swap(st.png);
    if (!s.waitForRows) {
        png_write_image(st.png, st.rows.data());
    } else {
        for (int y = 0; y < s.height; y += kPngBandRows) {
            const int n = std::min(kPngBandRows, s.height - y);
            s.waitForRows(y + n);
            png_write_rows(st.png, st.rows.data() + y, png_uint_32(n));
        }
    }
    png_write_end(st.png, nullptr);
    return true;
}

}  // namespace

Result<std::vector<unsigned char>> encodePng(const Samples& s, const EncodeOptions& options) {
    WriteState st;
    st.rows.resize(std::size_t(s.height));
    const std::size_t rowBytes =
        std::size_t(s.width) * std::size_t(s.channels) * sampleBytes(s.type);
    for (std::size_t y = 0; y < st.rows.size(); ++y) {
        st.rows[y] =
            const_cast<png_bytep>(static_cast<const unsigned char*>(s.data) + y * rowBytes);
    }
    st.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &st.errors, onError, onWarning);
    if (st.png) st.info = png_create_info_struct(st.png);
    if (!st.png || !st.info) return internalError("libpng could not start");
    if (!writeRows(st, s, options.pngCompression))
        return ioError("cannot encode PNG: " + st.errors.message);
    return std::move(st.bytes);
}

}  // namespace flarekit::codec
