// SPDX-License-Identifier: Apache-2.0
// Reading image files (ImageWrite.cpp writes them). PNG, JPEG, TIFF and EXR go through their own
// libraries (core/codecs), every other format through the OpenImageIO module, loaded only when such
// a file is met. Sizes, the pixels-per-byte ratio and the job's memory are checked from the header
// before any pixel memory is allocated, so a corrupt or hostile header cannot make flarekit
// allocate gigabytes.
#include "flarekit/ImageIO.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include <half.h>

#include "core/BandPipeline.h"
#include "core/FirstLine.h"
#include "core/HalfFloat.h"
#include "core/ImageIOShared.h"
#include "core/Parallel.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"
#include "flarekit/Color.h"
#include "flarekit/Limits.h"

namespace flarekit {

namespace fs = std::filesystem;
using codec::Format;
using codec::SampleType;
using imageio::forEachChunk;
using imageio::moduleFor;

namespace {

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

bool leftToOiio(const Error& e) {
    return e.message == codec::kUnsupportedLayout;
}

//! The file's samples through the codec its first bytes name, or through OpenImageIO.
Result<codec::Raw> readRaw(const std::string& path, Format format, const codec::HeaderCheck& check,
                           const codec::PngRowTarget* target = nullptr) {
    Result<codec::Raw> raw = invalidInput(codec::kUnsupportedLayout);
    if (format == Format::Png) raw = codec::readPng(path, check, target);
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

//! How decoded samples are laid out and read: kept by value, so a band converted while the
//! decoder still runs depends on nothing the codec is filling.
struct SampleView {
    int keep = 0;  //!< channels per pixel
    SampleType type = SampleType::U8;
    bool srgb = false;  //!< colour through the sRGB curve
    explicit SampleView(const codec::Raw& raw)
        : keep(raw.channels),
          type(raw.header.decodeAs),
          srgb(!raw.header.isFloat && !raw.header.declaredLinear) {}
    std::size_t pixelBytes() const { return std::size_t(keep) * codec::sampleBytes(type); }
};

//! `count` pixels of decoded samples (from `bytes`) to linear float RGBA (at `rgba`): integer
//! colour through the sRGB tables (unless the file says linear), floats as they are,
//! NaN as 0 and infinities as +-65504 (sanitisedSample). Returns how many were replaced.
std::size_t toLinearRgba(const SampleView& v, const unsigned char* bytes, float* rgba,
                         std::size_t count) {
    const int keep = v.keep;
    auto run = [&](auto sample, auto colour, auto alpha) {
        for (std::size_t p = 0; p < count; ++p) {
            promote(
                rgba + p * 4, p * std::size_t(keep), keep,
                [&](std::size_t i) { return colour(sample[i]); },
                [&](std::size_t i) { return alpha(sample[i]); });
        }
    };
    if (v.type == SampleType::U8) {
        const float* table = srgb8DecodeTable();
        auto linear = [](std::uint8_t s) { return float(s) * (1.f / 255.f); };
        if (v.srgb) {
            run(
                bytes, [table](std::uint8_t s) { return table[s]; }, linear);
        } else {
            run(bytes, linear, linear);
        }
        return 0;
    }
    if (v.type == SampleType::U16) {
        const float* table = srgb16DecodeTable();
        const auto* u16 = reinterpret_cast<const std::uint16_t*>(bytes);
        auto linear = [](std::uint16_t s) { return float(s) * (1.f / 65535.f); };
        if (v.srgb) {
            run(
                u16, [table](std::uint16_t s) { return table[s]; }, linear);
        } else {
            run(u16, linear, linear);
        }
        return 0;
    }
    const auto* f32 = reinterpret_cast<const float*>(bytes);
    std::size_t bad = 0;
    auto finite = [&](std::size_t i) {
        const float s = f32[i];
        if (std::isfinite(s)) return s;
        ++bad;
        return sanitisedSample(s);
    };
    auto colour = [&](std::size_t i) {
        const float s = finite(i);
        return v.srgb ? srgbToLinear(s) : s;
    };
    for (std::size_t p = 0; p < count; ++p)
        promote(rgba + p * 4, p * std::size_t(keep), keep, colour, finite);
    return bad;
}

//! The whole image, in parallel.
std::size_t toLinearRgba(const codec::Raw& raw, Image& image) {
    const SampleView view(raw);
    std::atomic<std::size_t> nonFinite{0};
    forEachChunk(image.pixelCount(), [&](std::size_t p0, std::size_t p1) {
        nonFinite += toLinearRgba(view, raw.bytes.data() + p0 * view.pixelBytes(),
                                  image.data() + p0 * 4, p1 - p0);
    });
    return nonFinite;
}

//! A PNG's rows converted band by band while libpng decodes the next ones: libpng decodes on
//! one thread, and the conversion was a third of the read when it followed. The decoded bands
//! go round a ring of kRingBands bands rather than into a buffer for the whole image, whose
//! first touch (6 MB at 1080p) was itself as long as the conversion; libpng waits for a slot
//! only when the conversion is that far behind.
struct ConvertWhileDecoding {
    //! Bands in flight: libpng's next band goes into the slot of the band this many before it.
    static constexpr int kRingBands = 8;
    Image& image;
    std::vector<unsigned char> ring;
    std::size_t bandBytes = 0;
    std::optional<BandPipeline> pipeline;  // after the ring: stopped before the ring goes
    std::atomic<std::size_t> nonFinite{0};

    unsigned char* slot(int y0) {
        return ring.data() + std::size_t(y0 / codec::kPngBandRows % kRingBands) * bandBytes;
    }

    unsigned char* rowsAt(const codec::Raw& raw, int y0) {
        if (!pipeline) {
            image = Image(raw.header.width, raw.header.height);
            const SampleView view(raw);
            const std::size_t width = std::size_t(raw.header.width);
            bandBytes = std::size_t(codec::kPngBandRows) * width * view.pixelBytes();
            ring.resize(bandBytes * kRingBands);
            pipeline.emplace(
                raw.header.height, codec::kPngBandRows,
                [this, view, width](int first, int end) {
                    nonFinite += toLinearRgba(view, slot(first), image.row(first),
                                              std::size_t(end - first) * width);
                },
                false);
        }
        // The slot's previous band (kRingBands before this one) must be converted first.
        pipeline->waitFor(y0 - (kRingBands - 1) * codec::kPngBandRows);
        return slot(y0);
    }
    void decoded(int rowEnd) {
        if (rowEnd < 0) {
            pipeline.reset();  // cancels the bands not begun, waits for the one being converted
            return;
        }
        pipeline->publish(rowEnd);
    }
};

}  // namespace

Result<std::vector<float>> channelByName(const LoadedImage& loaded, const std::string& name,
                                         const std::string& source) {
    const Image& img = loaded.image;
    std::vector<float> plane(img.pixelCount());
    static constexpr const char* kRgba[] = {"R", "G", "B", "A"};
    // Without an alpha channel in the file, A is only the promoted 1 (opaque): never a matte.
    const int rgbaChannels = loaded.hasAlpha ? 4 : 3;
    for (int c = 0; c < rgbaChannels; ++c) {
        if (name != kRgba[c]) continue;
        for (std::size_t i = 0; i < plane.size(); ++i)
            plane[i] = img.data()[4 * i + std::size_t(c)];
        return plane;
    }
    std::string known = loaded.hasAlpha ? "R, G, B, A" : "R, G, B";
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

Result<LoadedImage> readImage(const std::string& path, const JobMemory& job,
                              const ReadOptions& options) {
    if (Status s = checkReadable(path); !s) return s.error();
    const codec::HeaderCheck check = [&](const codec::Header& h) {
        return checkHeader(path, h, job);
    };
    const Format format = codec::sniffFormat(path);
    LoadedImage out;
    if (format == Format::Exr) {
        auto exr = codec::readExr(path, check, options.part, &out.exrParts);
        if (exr && out.exrParts.size() == 1) out.exrParts.clear();  // one part: nothing to say
        if (exr) {
            out.fileChannels = exr->header.channels;
            out.hasAlpha = exr->hasAlpha;
            out.wasFloat = true;
            // Channels past RGBA are kept in exrExtras, not dropped: an EXR output gets them back.
            out.exrExtras = exr->extras;
            out.extraChannels = exr->extras ? int(exr->extras->channels.size()) : 0;
            out.droppedChannels = 0;
            out.nonFinite = exr->nonFinite;
            out.halfExact = exr->allHalf;  // a non-finite half became 0, itself a half
            out.image = std::move(exr->image);
            return out;
        }
        if (!leftToOiio(exr.error()) || !options.part.empty()) return exr.error();
    }
    if (!options.part.empty())
        return invalidInput("--part " + excerpt(options.part, 60) + ": " + path +
                            " is not a multi-part EXR (parts are an OpenEXR feature)");
    ConvertWhileDecoding png{out.image, {}, 0, {}, {}};
    const codec::PngRowTarget target{
        [&](const codec::Raw& r, int y0, int) { return png.rowsAt(r, y0); },
        [&](int rowEnd) { png.decoded(rowEnd); }};
    auto raw = readRaw(path, format, check, &target);
    if (!raw) return raw.error();
    out.fileChannels = raw->header.channels;
    out.droppedChannels = raw->header.channels - raw->channels;
    out.wasFloat = raw->header.isFloat;
    out.hasAlpha = raw->channels == 2 || raw->channels == 4;
    out.decoderWarning = raw->warning;
    if (png.pipeline) {
        png.pipeline->finish();
        out.nonFinite = png.nonFinite;
    } else {
        out.image = Image(raw->header.width, raw->header.height);
        out.nonFinite = toLinearRgba(*raw, out.image);
    }
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
}  // namespace flarekit
