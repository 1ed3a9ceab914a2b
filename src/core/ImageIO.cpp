// Image files through OpenImageIO. Sizes are validated from the header before any pixel
// memory is allocated, so a corrupt or hostile header cannot make flarekit allocate gigabytes.
#include "flarekit/ImageIO.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "core/FirstLine.h"
#include "core/Parallel.h"
#include "core/SafeWrite.h"
#include "flarekit/Color.h"
#include "flarekit/Limits.h"

namespace flarekit {

namespace fs = std::filesystem;

namespace {

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

//! A header that claims far more pixels than its file could hold, or a job over the memory
//! budget: refused before anything is decoded.
Status checkClaimedSize(const std::string& path, const OIIO::ImageSpec& spec,
                        const JobMemory& job) {
    const ResourceLimits limits = resourceLimits();
    const double pixels =
        double(spec.width) * double(spec.height) * double(std::max(1, spec.depth));
    std::error_code ec;
    const auto fileBytes = fs::file_size(path, ec);
    if (!ec && pixels >= double(limits.ratioCheckFromPixels) &&
        pixels > limits.maxPixelsPerFileByte * double(std::max<std::uintmax_t>(fileBytes, 1))) {
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.0f",
                      pixels / double(std::max<std::uintmax_t>(fileBytes, 1)));
        return invalidInput(path + ": claims " + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) + " pixels in " +
                            std::to_string(fileBytes) + " bytes (" + ratio +
                            " pixels per byte; a decompression bomb or a truncated file): expected "
                            "at most " +
                            std::to_string(std::uint64_t(limits.maxPixelsPerFileByte)) +
                            " (raise it with --max-pixels-per-byte)");
    }
    const double decodeBytes = pixels * double(std::max(1, spec.nchannels)) * 4.0;
    const double need = job.fixedBytes + pixels * job.bytesPerPixel + decodeBytes;
    return checkMemory(path, need,
                       std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                           (job.detail.empty() ? "" : ", " + job.detail));
}

Result<std::unique_ptr<OIIO::ImageInput>> openInput(const std::string& path, const JobMemory& job) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return ioError(path + ": cannot read: no such file");
    if (fs::is_directory(path, ec)) return ioError(path + ": cannot read: is a directory");
    if (Status st = checkExrAttributeSizes(path); !st) return st.error();
    // Straight (unassociated) alpha in memory: without this hint OIIO's PNG reader multiplies
    // colour by alpha, which would change the bytes `flarekit blend` must use exactly.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        std::string why = firstLine(OIIO::geterror());
        return invalidInput(path +
                            ": cannot read image: " + (why.empty() ? "unknown format" : why));
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide ||
        spec.height > kMaxImageSide) {
        return invalidInput(path + ": image size " + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) + ": expected width and height in [1, " +
                            std::to_string(kMaxImageSide) + "]");
    }
    if (std::size_t(spec.width) * std::size_t(spec.height) > kMaxImagePixels) {
        return invalidInput(path + ": image size " + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) + ": expected at most " +
                            std::to_string(kMaxImagePixels) + " pixels");
    }
    if (spec.nchannels < 1) return invalidInput(path + ": image has no channels");
    if (Status st = checkClaimedSize(path, spec, job); !st) return st.error();
    // OIIO reads a movie as one subimage per frame; taking the first one silently would hide
    // that the rest were ignored.
    if (std::string(in->format_name()).rfind("FFmpeg", 0) == 0) {  // OIIO's "FFmpeg movie"
        return invalidInput(path +
                            ": is a video; flarekit reads still images (take a frame out with "
                            "`ffmpeg -i " +
                            path + " -frames:v 1 frame.png`)");
    }
    return in;
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

//! fn(i) for every i in [0, count), spread over the cores in chunks.
template <typename Fn>
void forEachSample(std::size_t count, Fn fn) {
    constexpr std::size_t kChunk = 1 << 16;
    parallelFor(0, int((count + kChunk - 1) / kChunk), 1, [&](int c0, int c1) {
        const std::size_t end = std::min(count, std::size_t(c1) * kChunk);
        for (std::size_t i = std::size_t(c0) * kChunk; i < end; ++i) fn(i);
    });
}

bool isFloatType(OIIO::TypeDesc type) {
    return type.basetype == OIIO::TypeDesc::HALF || type.basetype == OIIO::TypeDesc::FLOAT ||
           type.basetype == OIIO::TypeDesc::DOUBLE;
}

bool declaredLinear(const OIIO::ImageSpec& spec) {
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(cs.begin(), cs.end(), cs.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return cs == "linear" || cs == "lin_srgb" || cs == "scene_linear";
}

}  // namespace

Result<LoadedImage> readImage(const std::string& path, const JobMemory& job) {
    auto opened = openInput(path, job);
    if (!opened) return opened.error();
    auto& in = opened.value();
    const OIIO::ImageSpec spec = in->spec();
    const int keep = std::min(spec.nchannels, 4);
    LoadedImage out;
    out.fileChannels = spec.nchannels;
    out.droppedChannels = spec.nchannels - keep;
    out.wasFloat = isFloatType(spec.format);
    out.hasAlpha = keep == 2 || keep == 4;
    const bool decodeSrgb = !out.wasFloat && !declaredLinear(spec);
    // 8-bit sRGB files decode exactly through a 256-entry table; everything else as float.
    const bool bytes = spec.format == OIIO::TypeDesc::UINT8 && decodeSrgb;
    const std::size_t samples =
        std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(keep);
    std::vector<std::uint8_t> raw8(bytes ? samples : 0);
    std::vector<float> rawF(bytes ? 0 : samples);
    const bool read = bytes ? in->read_image(0, 0, 0, keep, OIIO::TypeDesc::UINT8, raw8.data())
                            : in->read_image(0, 0, 0, keep, OIIO::TypeDesc::FLOAT, rawF.data());
    if (!read) return invalidInput(path + ": cannot decode image: " + firstLine(in->geterror()));
    in->close();

    out.image = Image(spec.width, spec.height);
    std::atomic<std::size_t> nonFinite{0};
    parallelFor(0, spec.height, 16, [&](int y0, int y1) {
        std::size_t bad = 0;
        auto sample = [&](std::size_t i) -> float {
            if (bytes) return raw8[i] * (1.f / 255.f);
            const float v = rawF[i];
            if (std::isfinite(v)) return v;
            ++bad;
            return 0.f;
        };
        auto colour = [&](std::size_t i) {
            if (bytes) return srgb8ToLinear(raw8[i]);
            const float v = sample(i);
            return decodeSrgb ? srgbToLinear(v) : v;
        };
        for (std::size_t p = std::size_t(y0) * std::size_t(spec.width);
             p < std::size_t(y1) * std::size_t(spec.width); ++p) {
            const std::size_t s = p * std::size_t(keep);
            float* d = out.image.data() + p * 4;
            if (keep <= 2) {  // grey (+ alpha) promoted to RGB(A)
                d[0] = d[1] = d[2] = colour(s);
            } else {
                d[0] = colour(s);
                d[1] = colour(s + 1);
                d[2] = colour(s + 2);
            }
            d[3] = out.hasAlpha ? sample(s + std::size_t(keep) - 1) : 1.f;
        }
        nonFinite += bad;
    });
    out.nonFinite = nonFinite;
    out.image = reoriented(out.image, spec.get_int_attribute("Orientation", 1));
    return out;
}

namespace {
//! The OIIO writer for path's extension, or the error naming the unsupported extension. Only
//! writers that can encode into memory are used: the bytes are then committed by
//! writeFileSafely, which checks every write (OIIO's file writers do not all report a full disk).
Result<std::unique_ptr<OIIO::ImageOutput>> createOutput(const std::string& path) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->supports("ioproxy")) {
        return invalidInput(
            path + ": unsupported output format '" + lowerExtension(path) +
            "': expected .png, .jpg, .tif, .exr, .hdr, .bmp, .tga, .ppm, .webp or .dpx");
    }
    return out;
}
}  // namespace

Status checkOutputPath(const std::string& path) {
    if (Status s = checkWritablePath(path); !s) return s;
    auto out = createOutput(path);
    if (!out) return out.error();
    return Ok{};
}

namespace {

SampleFormat resolveFormat(const std::string& path, SampleFormat requested) {
    if (requested != SampleFormat::Auto) return requested;
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") return SampleFormat::Half;
    if (ext == ".hdr") return SampleFormat::Float;
    if (ext == ".tif" || ext == ".tiff") return SampleFormat::U16;
    return SampleFormat::U8;
}

//! Encodes through a writer from createOutput (chosen by the final name's extension) into
//! memory, then commits the bytes with writeFileSafely.
Status writeWithOiio(OIIO::ImageOutput& out, const std::string& path, const OIIO::ImageSpec& spec,
                     OIIO::TypeDesc dataType, const void* data) {
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    if (!out.set_ioproxy(&memory) || !out.open(path, spec) || !out.write_image(dataType, data) ||
        !out.close()) {
        return ioError(path + ": cannot encode: " + firstLine(out.geterror()));
    }
    return writeFileSafely(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

}  // namespace

SampleFormat outputSampleFormat(const std::string& path, SampleFormat requested) {
    return resolveFormat(path, requested);
}

bool holdsFloatSamples(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff";
}

Status writeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    if (Status s = checkOutputPath(path); !s) return s;
    auto out = createOutput(path);
    if (!out) return out.error();
    OIIO::ImageOutput& writer = **out;
    const bool alpha = options.alpha && writer.supports("alpha");
    const int channels = alpha ? 4 : 3;
    const SampleFormat format = resolveFormat(path, options.format);
    const bool isFloat = isFloatFormat(format);
    if (isFloat && !holdsFloatSamples(path)) {
        return invalidInput(path +
                            ": half/float samples need a float format (.exr, .tif, .hdr), not '" +
                            lowerExtension(path) + "'");
    }

    OIIO::TypeDesc fileType = format == SampleFormat::U8     ? OIIO::TypeDesc::UINT8
                              : format == SampleFormat::U16  ? OIIO::TypeDesc::UINT16
                              : format == SampleFormat::Half ? OIIO::TypeDesc::HALF
                                                             : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width(), image.height(), channels, fileType);
    if (alpha) {
        spec.alpha_channel = 3;
        spec.attribute("oiio:UnassociatedAlpha", 1);  // written as held: no division by alpha
    }
    spec.attribute("oiio:ColorSpace", isFloat ? "Linear" : "sRGB");
    spec.attribute("Software", "flarekit");

    // Convert to the file's encoding here so the code values are flarekit's, not a plugin's.
    const std::size_t count = image.pixelCount() * std::size_t(channels);
    const float* src = image.data();
    auto sample = [&](std::size_t i) {
        const std::size_t pixel = i / std::size_t(channels), c = i % std::size_t(channels);
        const float v = src[pixel * 4 + c];
        return std::isfinite(v) ? v : 0.f;
    };
    auto encode = [&](std::size_t i) {  // sRGB for colour, linear alpha, in [0, 1]
        const float v = std::clamp(sample(i), 0.f, 1.f);
        return i % std::size_t(channels) < 3 ? linearToSrgb(v) : v;
    };
    if (format == SampleFormat::U8) {
        std::vector<std::uint8_t> bytes(count);
        forEachSample(count, [&](std::size_t i) {
            bytes[i] = i % std::size_t(channels) < 3 ? linearToSrgb8(sample(i))
                                                     : std::uint8_t(std::lround(encode(i) * 255.f));
        });
        return writeWithOiio(writer, path, spec, OIIO::TypeDesc::UINT8, bytes.data());
    }
    if (format == SampleFormat::U16) {
        std::vector<std::uint16_t> words(count);
        forEachSample(count, [&](std::size_t i) {
            words[i] = std::uint16_t(std::lround(encode(i) * 65535.f));
        });
        return writeWithOiio(writer, path, spec, OIIO::TypeDesc::UINT16, words.data());
    }
    std::vector<float> linear(count);
    forEachSample(count, [&](std::size_t i) { linear[i] = sample(i); });
    return writeWithOiio(writer, path, spec, OIIO::TypeDesc::FLOAT, linear.data());
}

Result<Image8> readImage8(const std::string& path, const JobMemory& job) {
    auto opened = openInput(path, job);
    if (!opened) return opened.error();
    auto& in = opened.value();
    const OIIO::ImageSpec spec = in->spec();
    if (spec.format != OIIO::TypeDesc::UINT8) {
        return invalidInput(path + ": expected an 8-bit image, got " +
                            std::string(spec.format.c_str()) + " samples");
    }
    if (spec.nchannels > 4) {
        return invalidInput(path + ": expected 1 to 4 channels, got " +
                            std::to_string(spec.nchannels));
    }
    Image8 out;
    out.width = spec.width;
    out.height = spec.height;
    out.channels = spec.nchannels;
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, out.pixels.data())) {
        return invalidInput(path + ": cannot decode image: " + firstLine(in->geterror()));
    }
    return out;
}

Status writeImage8(const std::string& path, const Image8& image) {
    if (Status s = checkOutputPath(path); !s) return s;
    auto out = createOutput(path);
    if (!out) return out.error();
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
    if (image.channels == 2 || image.channels == 4) {
        spec.alpha_channel = image.channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    spec.attribute("Software", "flarekit");
    return writeWithOiio(**out, path, spec, OIIO::TypeDesc::UINT8, image.pixels.data());
}

}  // namespace flarekit
