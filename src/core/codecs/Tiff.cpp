// SPDX-License-Identifier: Apache-2.0
// TIFF through libtiff: the plain layouts (see Codecs.h); the rest goes to OpenImageIO.
#include <tiffio.h>

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <mutex>

#include "core/FirstLine.h"
#include "core/codecs/Codecs.h"

namespace flarekit::codec {

namespace {

//! libtiff's handlers are process-wide: the last error of this thread is kept for the message.
thread_local std::string lastTiffError;

void onTiffError(const char* module, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    lastTiffError = (module ? std::string(module) + ": " : std::string()) + text;
}
void onTiffWarning(const char*, const char*, va_list) {}

void installHandlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        TIFFSetErrorHandler(onTiffError);
        TIFFSetWarningHandler(onTiffWarning);
    });
}

struct TiffFile {
    TIFF* tif = nullptr;
    ~TiffFile() {
        if (tif) TIFFClose(tif);
    }
};

Error decodeError(const std::string& path) {
    return invalidInput(path + ": cannot decode image: " +
                        excerpt(lastTiffError.empty() ? "libtiff error" : lastTiffError, 200));
}

}  // namespace

Result<Raw> readTiff(const std::string& path, const HeaderCheck& check) {
    installHandlers();
    lastTiffError.clear();
    TiffFile file;
    file.tif = TIFFOpen(path.c_str(), "r");
    if (!file.tif) return decodeError(path);
    TIFF* tif = file.tif;
    std::uint32_t width = 0, height = 0;
    std::uint16_t samples = 1, bits = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG,
                  photometric = PHOTOMETRIC_MINISBLACK, orientation = ORIENTATION_TOPLEFT;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
    TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photometric);
    TIFFGetFieldDefaulted(tif, TIFFTAG_ORIENTATION, &orientation);
    const bool plainPhotometric =
        photometric == PHOTOMETRIC_MINISBLACK || photometric == PHOTOMETRIC_RGB;
    const bool integer = format == SAMPLEFORMAT_UINT && (bits == 8 || bits == 16);
    const bool real = format == SAMPLEFORMAT_IEEEFP && bits == 32;
    if (!plainPhotometric || planar != PLANARCONFIG_CONTIG || !(integer || real) || samples < 1 ||
        (photometric == PHOTOMETRIC_RGB && samples < 3)) {
        return invalidInput(kUnsupportedLayout);
    }
    Raw raw;
    raw.header.width = int(std::min<std::uint32_t>(width, 1u << 30));
    raw.header.height = int(std::min<std::uint32_t>(height, 1u << 30));
    raw.header.channels = samples;
    raw.header.isFloat = real;
    raw.header.decodeAs = real ? SampleType::F32 : bits == 16 ? SampleType::U16 : SampleType::U8;
    raw.header.format = "tiff";
    if (Status s = check(raw.header); !s) return s.error();
    raw.channels = std::min<int>(samples, 4);
    raw.orientation = orientation;
    const std::size_t sample = sampleBytes(raw.header.decodeAs);
    const std::size_t filePixel = sample * samples, keptPixel = sample * std::size_t(raw.channels);
    raw.bytes.resize(raw.sampleCount() * sample);
    // Decoded chunks (strips or tiles) land in `chunk`, then their kept channels are copied to
    // their place in the image.
    std::vector<unsigned char> chunk(TIFFIsTiled(tif) ? std::size_t(TIFFTileSize(tif))
                                                      : std::size_t(TIFFStripSize(tif)));
    auto place = [&](std::uint32_t x0, std::uint32_t y0, std::uint32_t w, std::uint32_t rows,
                     std::size_t chunkRowBytes) {
        for (std::uint32_t r = 0; r < rows && y0 + r < height; ++r) {
            const unsigned char* from = chunk.data() + r * chunkRowBytes;
            unsigned char* to = raw.bytes.data() + (std::size_t(y0 + r) * width + x0) * keptPixel;
            const std::uint32_t n = std::min(w, width - x0);
            if (filePixel == keptPixel) {
                std::memcpy(to, from, n * keptPixel);
            } else {
                for (std::uint32_t x = 0; x < n; ++x)
                    std::memcpy(to + x * keptPixel, from + x * filePixel, keptPixel);
            }
        }
    };
    if (TIFFIsTiled(tif)) {
        std::uint32_t tileW = 0, tileH = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tileW);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &tileH);
        if (tileW == 0 || tileH == 0) return decodeError(path);
        for (std::uint32_t y = 0; y < height; y += tileH) {
            for (std::uint32_t x = 0; x < width; x += tileW) {
                if (TIFFReadTile(tif, chunk.data(), x, y, 0, 0) < 0) return decodeError(path);
                place(x, y, tileW, tileH, tileW * filePixel);
            }
        }
    } else {
        std::uint32_t rowsPerStrip = height;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rowsPerStrip);
        rowsPerStrip = std::clamp<std::uint32_t>(rowsPerStrip, 1, height);
        for (std::uint32_t y = 0, strip = 0; y < height; y += rowsPerStrip, ++strip) {
            if (TIFFReadEncodedStrip(tif, strip, chunk.data(), tmsize_t(chunk.size())) < 0)
                return decodeError(path);
            place(0, y, width, rowsPerStrip, std::size_t(width) * filePixel);
        }
    }
    return raw;
}

namespace {

//! An in-memory TIFF stream for TIFFClientOpen: the encoded file grows in `bytes`.
struct MemoryTiff {
    std::vector<unsigned char> bytes;
    std::size_t at = 0;

    static tmsize_t read(thandle_t, void*, tmsize_t) { return 0; }
    static tmsize_t write(thandle_t h, void* data, tmsize_t size) {
        auto* m = static_cast<MemoryTiff*>(h);
        if (m->at + std::size_t(size) > m->bytes.size()) m->bytes.resize(m->at + std::size_t(size));
        std::memcpy(m->bytes.data() + m->at, data, std::size_t(size));
        m->at += std::size_t(size);
        return size;
    }
    static toff_t seek(thandle_t h, toff_t offset, int whence) {
        auto* m = static_cast<MemoryTiff*>(h);
        const std::size_t base = whence == SEEK_SET   ? 0
                                 : whence == SEEK_CUR ? m->at
                                                      : m->bytes.size();
        m->at = base + std::size_t(offset);
        return m->at;
    }
    static int close(thandle_t) { return 0; }
    static toff_t size(thandle_t h) { return static_cast<MemoryTiff*>(h)->bytes.size(); }
    static int map(thandle_t, void**, toff_t*) { return 0; }
    static void unmap(thandle_t, void*, toff_t) {}
};

}  // namespace

Result<std::vector<unsigned char>> encodeTiff(const Samples& s, const EncodeOptions&) {
    installHandlers();
    lastTiffError.clear();
    MemoryTiff memory;
    TiffFile file;
    file.tif = TIFFClientOpen("memory", "w", &memory, MemoryTiff::read, MemoryTiff::write,
                              MemoryTiff::seek, MemoryTiff::close, MemoryTiff::size,
                              MemoryTiff::map, MemoryTiff::unmap);
    if (!file.tif) return ioError("cannot encode TIFF: " + lastTiffError);
    TIFF* tif = file.tif;
    const std::size_t sample = sampleBytes(s.type);
    const std::size_t rowBytes = std::size_t(s.width) * std::size_t(s.channels) * sample;
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(s.width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(s.height));
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(s.channels));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(sample * 8));
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT,
                 s.type == SampleType::F32 ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC,
                 s.channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    if (s.channels == 2 || s.channels == 4) {
        const std::uint16_t extra[] = {EXTRASAMPLE_UNASSALPHA};
        TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, extra);
    }
    // Deflate with the horizontal predictor (floating-point predictor for floats): what
    // OpenImageIO wrote by default ("zip").
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR,
                 s.type == SampleType::F32 ? PREDICTOR_FLOATINGPOINT : PREDICTOR_HORIZONTAL);
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(tif, 0));
    TIFFSetField(tif, TIFFTAG_SOFTWARE, "flarekit");
    std::vector<unsigned char> row(rowBytes);  // TIFFWriteScanline may modify its input
    for (int y = 0; y < s.height; ++y) {
        std::memcpy(row.data(),
                    static_cast<const unsigned char*>(s.data) + std::size_t(y) * rowBytes,
                    rowBytes);
        if (TIFFWriteScanline(tif, row.data(), std::uint32_t(y), 0) < 0)
            return ioError("cannot encode TIFF: " + lastTiffError);
    }
    TIFFClose(tif);
    file.tif = nullptr;
    return std::move(memory.bytes);
}

}  // namespace flarekit::codec
