// Image files. PNG, JPEG, TIFF and EXR go through their own libraries (core/codecs), every
// other format through the OpenImageIO module, loaded only when such a file is met. Sizes,
// the pixels-per-byte ratio and the job's memory are checked from the header before any pixel
// memory is allocated, so a corrupt or hostile header cannot make flarekit allocate gigabytes.
#include "flarekit/ImageIO.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <vector>

#include <half.h>

#include "core/FirstLine.h"
#include "core/HalfFloat.h"
#include "core/Parallel.h"
#include "core/SafeWrite.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"
#include "core/codecs/OiioModule.h"
#include "flarekit/Color.h"
#include "flarekit/Limits.h"

namespace flarekit {

namespace fs = std::filesystem;
using codec::Format;
using codec::SampleType;

namespace {

std::atomic<int> g_pngCompression{codec::EncodeOptions{}.pngCompression};
std::mutex g_exrMutex;
std::string g_exrCompression = codec::EncodeOptions{}.exrCompression;
bool g_exrCompressionChosen = false;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

//! OpenEXR reads each header attribute by allocating the size the file states before reading
//! it, so a 500-byte file claiming a 1.6 GB string costs 1.6 GB and half a minute (a fuzzer
//! find). The attribute list (name, type, int32 size, value; an empty name ends a header, as in
//! the OpenEXR file layout) is walked first and a size past the end of the file refused.
Status checkExrAttributeSizes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[8] = {};
    if (!in.read(reinterpret_cast<char*>(magic), 8)) return Ok{};
    if (magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01) return Ok{};
    const bool multipart = (magic[5] & 0x10) != 0;  // version flag bit 12
    std::error_code ec;
    const auto fileBytes = std::uintmax_t(fs::file_size(path, ec));
    if (ec) return Ok{};
    auto readName = [&](std::string& out) {
        out.clear();
        for (char c; in.get(c);) {
            if (c == '\0') return true;
            if (out.size() < 256) out += c;
        }
        return false;
    };
    for (int header = 0; header < 1024; ++header) {
        std::string name, type;
        if (!readName(name)) return Ok{};  // truncated: OpenEXR reports it
        if (name.empty()) {
            if (!multipart || header > 0) return Ok{};
            continue;
        }
        for (int attributes = 0; !name.empty() && attributes < 100000; ++attributes) {
            unsigned char size[4] = {};
            if (!readName(type) || !in.read(reinterpret_cast<char*>(size), 4)) return Ok{};
            const std::int64_t bytes =
                std::int32_t(std::uint32_t(size[0]) | std::uint32_t(size[1]) << 8 |
                             std::uint32_t(size[2]) << 16 | std::uint32_t(size[3]) << 24);
            const auto at = std::uintmax_t(in.tellg());
            if (bytes < 0 || std::uintmax_t(bytes) > fileBytes - std::min(at, fileBytes)) {
                return invalidInput(path + ": EXR header attribute '" + excerpt(name, 60) +
                                    "' claims " + std::to_string(bytes) + " bytes, more than the " +
                                    std::to_string(fileBytes - std::min(at, fileBytes)) +
                                    " left in the file");
            }
            in.seekg(std::streamoff(bytes), std::ios::cur);
            if (!readName(name)) return Ok{};
        }
        if (!multipart) return Ok{};
    }
    return Ok{};
}

//! Sizes, then a header that claims far more pixels than its file could hold, then a job over
//! the memory budget: refused before anything is decoded.
Status checkHeader(const std::string& path, const codec::Header& header, const JobMemory& job) {
    if (header.width < 1 || header.height < 1 || header.width > kMaxImageSide ||
        header.height > kMaxImageSide) {
        return invalidInput(path + ": image size " + std::to_string(header.width) + "x" +
                            std::to_string(header.height) + ": expected width and height in [1, " +
                            std::to_string(kMaxImageSide) + "]");
    }
    if (std::size_t(header.width) * std::size_t(header.height) > kMaxImagePixels) {
        return invalidInput(path + ": image size " + std::to_string(header.width) + "x" +
                            std::to_string(header.height) + ": expected at most " +
                            std::to_string(kMaxImagePixels) + " pixels");
    }
    if (header.channels < 1) return invalidInput(path + ": image has no channels");
    const ResourceLimits limits = resourceLimits();
    const double pixels = double(header.width) * double(header.height);
    std::error_code ec;
    const auto fileBytes = fs::file_size(path, ec);
    if (!ec && pixels >= double(limits.ratioCheckFromPixels) &&
        pixels > limits.maxPixelsPerFileByte * double(std::max<std::uintmax_t>(fileBytes, 1))) {
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.0f",
                      pixels / double(std::max<std::uintmax_t>(fileBytes, 1)));
        return invalidInput(path + ": claims " + std::to_string(header.width) + "x" +
                            std::to_string(header.height) + " pixels in " +
                            std::to_string(fileBytes) + " bytes (" + ratio +
                            " pixels per byte; a decompression bomb or a truncated file): expected "
                            "at most " +
                            std::to_string(std::uint64_t(limits.maxPixelsPerFileByte)) +
                            " (raise it with --max-pixels-per-byte)");
    }
    const double decodeBytes =
        pixels * double(std::min(header.channels, 4)) * double(codec::sampleBytes(header.decodeAs));
    const double need =
        job.fixedBytes + pixels * (job.bytesPerPixel + header.extraBytesPerPixel) + decodeBytes;
    return checkMemory(path, need,
                       std::to_string(header.width) + "x" + std::to_string(header.height) +
                           (job.detail.empty() ? "" : ", " + job.detail));
}

Status checkReadable(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return ioError(path + ": cannot read: no such file");
    if (fs::is_directory(path, ec)) return ioError(path + ": cannot read: is a directory");
    return checkExrAttributeSizes(path);
}

const codec::OiioModule* moduleFor(const std::string& what, Error* error) {
    std::string why;
    const codec::OiioModule* m = codec::oiioModule(&why);
    if (!m && error) {
        *error = internalError(what +
                               " needs flarekit's OpenImageIO module, which could not be "
                               "loaded: " +
                               excerpt(why, 300));
    }
    return m;
}

bool leftToOiio(const Error& e) {
    return e.message == codec::kUnsupportedLayout;
}

//! The file's samples through the codec its first bytes name, or through OpenImageIO.
Result<codec::Raw> readRaw(const std::string& path, Format format,
                           const codec::HeaderCheck& check) {
    Result<codec::Raw> raw = invalidInput(codec::kUnsupportedLayout);
    if (format == Format::Png) raw = codec::readPng(path, check);
    if (format == Format::Jpeg) raw = codec::readJpeg(path, check);
    if (format == Format::Tiff) raw = codec::readTiff(path, check);
    if (raw.ok() || !leftToOiio(raw.error())) return raw;
    Error error;
    const codec::OiioModule* m = moduleFor(path + ": reading this file", &error);
    if (!m) return error;
    return m->read(path, check);
}

//! The image as it is meant to be seen: EXIF orientation (1-8, as a phone stores a portrait
//! sideways with orientation 6) applied by moving pixels; 1 or an unknown value: unchanged.
Image reoriented(const Image& src, int orientation) {
    if (orientation < 2 || orientation > 8) return src;
    const int w = src.width(), h = src.height();
    const bool swap = orientation >= 5;
    Image dst(swap ? h : w, swap ? w : h);
    parallelFor(0, h, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = 0; x < w; ++x) {
                int dx = x, dy = y;
                switch (orientation) {
                    case 2:
                        dx = w - 1 - x;
                        break;  // mirrored left-right
                    case 3:
                        dx = w - 1 - x, dy = h - 1 - y;
                        break;  // upside down
                    case 4:
                        dy = h - 1 - y;
                        break;  // mirrored top-bottom
                    case 5:
                        dx = y, dy = x;
                        break;  // transposed
                    case 6:
                        dx = h - 1 - y, dy = x;
                        break;  // turned 90 degrees CW
                    case 7:
                        dx = h - 1 - y, dy = w - 1 - x;
                        break;  // transversed
                    case 8:
                        dx = y, dy = w - 1 - x;
                        break;  // turned 90 degrees CCW
                }
                dst.at(dx, dy) = src.at(x, y);
            }
        }
    });
    return dst;
}

//! fn(i0, i1) over [0, count) in chunks spread over the cores.
template <typename Fn>
void forEachChunk(std::size_t count, Fn fn) {
    constexpr std::size_t kChunk = 1 << 15;
    parallelFor(0, int((count + kChunk - 1) / kChunk), 1, [&](int c0, int c1) {
        fn(std::size_t(c0) * kChunk, std::min(count, std::size_t(c1) * kChunk));
    });
}

//! One pixel of `keep` samples (1 grey, 2 grey+alpha, 3 RGB, 4 RGBA) to RGBA, through
//! `colour` and `alpha` (sample index to value).
template <typename Colour, typename Alpha>
inline void promote(float* d, std::size_t s, int keep, Colour colour, Alpha alpha) {
    if (keep <= 2) {
        d[0] = d[1] = d[2] = colour(s);
    } else {
        d[0] = colour(s);
        d[1] = colour(s + 1);
        d[2] = colour(s + 2);
    }
    d[3] = keep == 2 || keep == 4 ? alpha(s + std::size_t(keep) - 1) : 1.f;
}

//! Decoded samples to linear float RGBA: integer colour through the sRGB tables (unless the
//! file says linear), floats as they are, non-finite values replaced by 0 and counted.
std::size_t toLinearRgba(const codec::Raw& raw, Image& image) {
    const int keep = raw.channels;
    const bool srgb = !raw.header.isFloat && !raw.header.declaredLinear;
    std::atomic<std::size_t> nonFinite{0};
    auto run = [&](auto sample, auto colour, auto alpha) {
        forEachChunk(image.pixelCount(), [&](std::size_t p0, std::size_t p1) {
            for (std::size_t p = p0; p < p1; ++p) {
                promote(
                    image.data() + p * 4, p * std::size_t(keep), keep,
                    [&](std::size_t i) { return colour(sample[i]); },
                    [&](std::size_t i) { return alpha(sample[i]); });
            }
        });
    };
    if (raw.header.decodeAs == SampleType::U8) {
        const float* table = srgb8DecodeTable();
        auto linear = [](std::uint8_t v) { return float(v) * (1.f / 255.f); };
        if (srgb) {
            run(
                raw.bytes.data(), [table](std::uint8_t v) { return table[v]; }, linear);
        } else {
            run(raw.bytes.data(), linear, linear);
        }
    } else if (raw.header.decodeAs == SampleType::U16) {
        const float* table = srgb16DecodeTable();
        const auto* u16 = reinterpret_cast<const std::uint16_t*>(raw.bytes.data());
        auto linear = [](std::uint16_t v) { return float(v) * (1.f / 65535.f); };
        if (srgb) {
            run(
                u16, [table](std::uint16_t v) { return table[v]; }, linear);
        } else {
            run(u16, linear, linear);
        }
    } else {
        const auto* f32 = reinterpret_cast<const float*>(raw.bytes.data());
        forEachChunk(image.pixelCount(), [&](std::size_t p0, std::size_t p1) {
            std::size_t bad = 0;
            auto finite = [&](std::size_t i) {
                const float v = f32[i];
                if (std::isfinite(v)) return v;
                ++bad;
                return 0.f;
            };
            auto colour = [&](std::size_t i) {
                const float v = finite(i);
                return srgb ? srgbToLinear(v) : v;
            };
            for (std::size_t p = p0; p < p1; ++p)
                promote(image.data() + p * 4, p * std::size_t(keep), keep, colour, finite);
            nonFinite += bad;
        });
    }
    return nonFinite;
}

//! After an EXR read into RGBA: grey copied to G and B, non-finite values replaced and counted.
std::size_t finishExr(Image& image, bool grey) {
    std::atomic<std::size_t> nonFinite{0};
    forEachChunk(image.pixelCount(), [&](std::size_t p0, std::size_t p1) {
        std::size_t bad = 0;
        for (float* d = image.data() + p0 * 4; d < image.data() + p1 * 4; d += 4) {
            if (grey) d[1] = d[2] = d[0];
            for (int c = 0; c < 4; ++c) {
                if (!std::isfinite(d[c])) {
                    d[c] = 0.f;
                    ++bad;
                }
            }
        }
        nonFinite += bad;
    });
    return nonFinite;
}

}  // namespace

void setPngCompression(int level) {
    g_pngCompression = std::clamp(level, 0, 9);
}
int pngCompression() {
    return g_pngCompression;
}

std::vector<std::string> exrCompressionNames() {
    return codec::exrCompressionNames();
}

Status setExrCompression(const std::string& name) {
    const std::vector<std::string> names = codec::exrCompressionNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        return invalidInput("EXR compression: expected one of " + list + ", got '" +
                            excerpt(name, 60) + "'");
    }
    std::lock_guard lock(g_exrMutex);
    g_exrCompression = name;
    g_exrCompressionChosen = true;
    return Ok{};
}
bool exrCompressionChosen() {
    std::lock_guard lock(g_exrMutex);
    return g_exrCompressionChosen;
}
std::string exrCompression() {
    std::lock_guard lock(g_exrMutex);
    return g_exrCompression;
}

Result<std::vector<float>> channelByName(const LoadedImage& loaded, const std::string& name,
                                         const std::string& source) {
    const Image& img = loaded.image;
    std::vector<float> plane(img.pixelCount());
    static constexpr const char* kRgba[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        if (name != kRgba[c]) continue;
        for (std::size_t i = 0; i < plane.size(); ++i)
            plane[i] = img.data()[4 * i + std::size_t(c)];
        return plane;
    }
    std::string known = "R, G, B, A";
    if (const ExrExtras* extras = loaded.exrExtras.get()) {
        for (const ExrExtraChannel& e : extras->channels) {
            known += ", " + e.name;
            if (e.name != name) continue;
            for (std::size_t i = 0; i < plane.size(); ++i) {
                const char* p = e.pixels.data();
                switch (e.channel.type) {
                    case Imf::HALF: {
                        half h;
                        std::memcpy(&h, p + 2 * i, 2);
                        plane[i] = float(h);
                        break;
                    }
                    case Imf::FLOAT:
                        std::memcpy(&plane[i], p + 4 * i, 4);
                        break;
                    default: {
                        std::uint32_t u = 0;
                        std::memcpy(&u, p + 4 * i, 4);
                        plane[i] = float(u);
                    }
                }
            }
            return plane;
        }
    }
    return invalidInput(source + ": no channel '" + excerpt(name, 60) +
                        "' (it has: " + excerpt(known, 400) + ")");
}

Result<LoadedImage> readImage(const std::string& path, const JobMemory& job) {
    if (Status s = checkReadable(path); !s) return s.error();
    const codec::HeaderCheck check = [&](const codec::Header& h) {
        return checkHeader(path, h, job);
    };
    const Format format = codec::sniffFormat(path);
    LoadedImage out;
    if (format == Format::Exr) {
        auto exr = codec::readExr(path, check);
        if (exr) {
            out.fileChannels = exr->header.channels;
            out.hasAlpha = exr->hasAlpha;
            out.wasFloat = true;
            // Channels past RGBA are kept in exrExtras, not dropped: an EXR output gets them back.
            out.exrExtras = exr->extras;
            out.extraChannels = exr->extras ? int(exr->extras->channels.size()) : 0;
            out.droppedChannels = 0;
            out.nonFinite = finishExr(exr->image, exr->grey);
            out.halfExact = exr->allHalf;  // a non-finite half became 0, itself a half
            out.image = std::move(exr->image);
            return out;
        }
        if (!leftToOiio(exr.error())) return exr.error();
    }
    auto raw = readRaw(path, format, check);
    if (!raw) return raw.error();
    out.fileChannels = raw->header.channels;
    out.droppedChannels = raw->header.channels - raw->channels;
    out.wasFloat = raw->header.isFloat;
    out.hasAlpha = raw->channels == 2 || raw->channels == 4;
    out.image = Image(raw->header.width, raw->header.height);
    out.nonFinite = toLinearRgba(*raw, out.image);
    raw->bytes = {};  // the decode buffer goes before reorienting copies the image
    if (raw->orientation >= 2 && raw->orientation <= 8)
        out.image = reoriented(out.image, raw->orientation);
    return out;
}

Result<Image8> readImage8(const std::string& path, const JobMemory& job) {
    if (Status s = checkReadable(path); !s) return s.error();
    const codec::HeaderCheck check = [&](const codec::Header& h) -> Status {
        if (h.decodeAs != SampleType::U8) {
            return invalidInput(path + ": expected an 8-bit image, got " +
                                (h.isFloat                       ? "float"
                                 : h.decodeAs == SampleType::U16 ? "uint16"
                                                                 : "wider") +
                                " samples");
        }
        if (h.channels > 4) {
            return invalidInput(path + ": expected 1 to 4 channels, got " +
                                std::to_string(h.channels));
        }
        return checkHeader(path, h, job);
    };
    Format format = codec::sniffFormat(path);
    if (format == Format::Exr) {  // always float: refused by the check without decoding
        codec::Header h;
        h.width = h.height = h.channels = 1;
        h.isFloat = true;
        h.decodeAs = SampleType::F32;
        if (Status s = check(h); !s) return s.error();
    }
    auto raw = readRaw(path, format, check);
    if (!raw) return raw.error();
    Image8 out;
    out.width = raw->header.width;
    out.height = raw->header.height;
    out.channels = raw->channels;
    out.pixels = std::move(raw->bytes);
    return out;
}

namespace {

struct Writer {
    Format format = Format::Other;
    bool alpha = true;  //!< the format holds an alpha channel
    const codec::OiioModule* module = nullptr;
};

//! The writer for path's extension, or the error naming the unsupported extension. Formats
//! OpenImageIO writes are used only where it can encode into memory: the bytes are then
//! committed by writeFileSafely, which checks every write.
Result<Writer> writerFor(const std::string& path) {
    const std::string ext = lowerExtension(path);
    Writer w;
    w.format = codec::formatForExtension(ext);
    if (w.format != Format::Other) {
        w.alpha = w.format != Format::Jpeg;
        return w;
    }
    Error error;
    w.module = moduleFor(path + ": writing '" + ext + "'", &error);
    if (!w.module) return error;
    if (!w.module->canWrite(path, &w.alpha)) {
        return invalidInput(
            path + ": unsupported output format '" + ext +
            "': expected .png, .jpg, .tif, .exr, .hdr, .bmp, .tga, .ppm, .webp or .dpx");
    }
    return w;
}

Status encodeAndWrite(const std::string& path, const Writer& w, const codec::Samples& s) {
    codec::EncodeOptions options;
    options.pngCompression = g_pngCompression;
    options.exrCompression = exrCompression();
    Result<std::vector<unsigned char>> bytes = internalError("no encoder");
    switch (w.format) {
        case Format::Png:
            bytes = codec::encodePng(s, options);
            break;
        case Format::Jpeg:
            bytes = codec::encodeJpeg(s, options);
            break;
        case Format::Tiff:
            bytes = codec::encodeTiff(s, options);
            break;
        case Format::Exr:
            bytes = codec::encodeExr(s, options);
            break;
        case Format::Other:
            bytes = w.module->encode(path, s);
            break;
    }
    if (!bytes) {
        Error e = bytes.error();
        if (e.message.rfind(path, 0) != 0) e.message = path + ": " + e.message;
        return e;
    }
    return writeFileSafely(path, {reinterpret_cast<const char*>(bytes->data()), bytes->size()});
}

SampleFormat resolveFormat(const std::string& path, SampleFormat requested) {
    if (requested != SampleFormat::Auto) return requested;
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") return SampleFormat::Half;
    if (ext == ".hdr") return SampleFormat::Float;
    if (ext == ".tif" || ext == ".tiff") return SampleFormat::U16;
    return SampleFormat::U8;
}

bool allFinite(const Image& image) {
    std::atomic<bool> finite{true};
    forEachChunk(image.pixelCount() * 4, [&](std::size_t i0, std::size_t i1) {
        bool ok = true;
        for (std::size_t i = i0; i < i1; ++i) ok &= std::isfinite(image.data()[i]);
        if (!ok) finite = false;
    });
    return finite;
}

}  // namespace

Status checkOutputPath(const std::string& path) {
    if (Status s = checkWritablePath(path); !s) return s;
    auto w = writerFor(path);
    if (!w) return w.error();
    return Ok{};
}

SampleFormat outputSampleFormat(const std::string& path, SampleFormat requested) {
    return resolveFormat(path, requested);
}

bool holdsFloatSamples(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff";
}

Status writeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    if (Status s = checkWritablePath(path); !s) return s;
    auto writer = writerFor(path);
    if (!writer) return writer.error();
    const bool alpha = options.alpha && writer->alpha;
    const int channels = alpha ? 4 : 3;
    // An EXR's own extras come back only to an EXR of the same size (its data window's).
    const ExrExtras* extras = options.exrExtras.get();
    if (extras) {
        const Imath::Box2i w = extras->header.dataWindow();
        if (writer->format != Format::Exr || long(w.max.x) - w.min.x + 1 != image.width() ||
            long(w.max.y) - w.min.y + 1 != image.height())
            extras = nullptr;
    }
    SampleFormat format = resolveFormat(path, options.format);
    if (extras && options.format == SampleFormat::Auto)
        format = extras->rgbHalf ? SampleFormat::Half : SampleFormat::Float;
    const bool isFloat = isFloatFormat(format);
    if (isFloat && !holdsFloatSamples(path)) {
        return invalidInput(path +
                            ": half/float samples need a float format (.exr, .tif, .hdr), not '" +
                            lowerExtension(path) + "'");
    }
    codec::Samples s;
    s.width = image.width();
    s.height = image.height();
    s.extras = extras;
    s.chosenCompression = exrCompressionChosen();
    s.channels = channels;
    s.srgb = !isFloat && options.srgbEncode;
    const std::size_t pixels = image.pixelCount();
    // Encoded here, so the code values are flarekit's, not a library's.
    const auto encodeAs = [&](auto code, SampleType type, auto encode) {
        std::vector<decltype(code)> codes(pixels * std::size_t(channels));
        forEachChunk(pixels, [&](std::size_t p0, std::size_t p1) {
            encode(image.data() + p0 * 4, p1 - p0, channels,
                   codes.data() + p0 * std::size_t(channels));
        });
        s.type = type;
        s.data = codes.data();
        return encodeAndWrite(path, *writer, s);
    };
    if (format == SampleFormat::U8)
        return encodeAs(std::uint8_t{}, SampleType::U8,
                        options.srgbEncode ? encodeSrgb8 : encodeDirect8);
    if (format == SampleFormat::U16)
        return encodeAs(std::uint16_t{}, SampleType::U16,
                        options.srgbEncode ? encodeSrgb16 : encodeDirect16);
    // Floats, linear, NaN and infinities as 0. EXR takes the image's own pixels (strided) when
    // they are all finite, or half floats converted here; other writers take packed samples.
    s.type = SampleType::F32;
    s.half = format == SampleFormat::Half;
    if (writer->format == Format::Exr && s.half) {
        std::vector<std::uint16_t> halves(pixels * std::size_t(channels));
        forEachChunk(pixels, [&](std::size_t p0, std::size_t p1) {
            floatsToHalf(image.data() + p0 * 4, p1 - p0, channels,
                         halves.data() + p0 * std::size_t(channels));
        });
        s.data = halves.data();
        return encodeAndWrite(path, *writer, s);
    }
    if (writer->format == Format::Exr && allFinite(image)) {
        s.data = image.data();
        s.pixelStride = 4 * sizeof(float);
        return encodeAndWrite(path, *writer, s);
    }
    std::vector<float> linear(pixels * std::size_t(channels));
    forEachChunk(pixels, [&](std::size_t p0, std::size_t p1) {
        for (std::size_t p = p0; p < p1; ++p) {
            for (int c = 0; c < channels; ++c) {
                const float v = image.data()[p * 4 + std::size_t(c)];
                linear[p * std::size_t(channels) + std::size_t(c)] = std::isfinite(v) ? v : 0.f;
            }
        }
    });
    s.data = linear.data();
    return encodeAndWrite(path, *writer, s);
}

Status writeImage8(const std::string& path, const Image8& image) {
    if (Status s = checkWritablePath(path); !s) return s;
    auto writer = writerFor(path);
    if (!writer) return writer.error();
    Writer w = *writer;
    // JPEG holds no alpha: grey+alpha and RGBA go to OpenImageIO's writer, as before.
    if (w.format == Format::Jpeg && (image.channels == 2 || image.channels == 4)) {
        Error error;
        w.module = moduleFor(path + ": writing JPEG with alpha", &error);
        if (!w.module) return error;
        w.format = Format::Other;
    }
    codec::Samples s;
    s.width = image.width;
    s.height = image.height;
    s.channels = image.channels;
    s.type = SampleType::U8;
    s.data = image.pixels.data();
    return encodeAndWrite(path, w, s);
}

}  // namespace flarekit
