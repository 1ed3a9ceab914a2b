// SPDX-License-Identifier: Apache-2.0
// Writing image files: every format encoded in memory (PNG, JPEG, TIFF and EXR by their own
// libraries, the rest by the OpenImageIO module) and committed by writeFileSafely; the PNG and
// EXR compression settings; an EXR input's extras given back to an EXR output.
#include <algorithm>
#include <atomic>
#include <vector>

#include "core/HalfFloat.h"
#include "core/ImageIOShared.h"
#include "core/Interrupt.h"
#include "core/SafeWrite.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"
#include "flarekit/ParamText.h"

namespace flarekit {

using codec::Format;
using codec::SampleType;
using imageio::forEachChunk;
using imageio::lowerExtension;
using imageio::moduleFor;

std::vector<std::string> exrCompressionNames() {
    return codec::exrCompressionNames();
}

Status checkEncodeSettings(const EncodeSettings& settings) {
    if (Status s = validateParams<EncodeSettings>(settings, kEncodeParams, ""); !s) return s;
    if (settings.exrCompression.empty()) return Ok{};
    const std::vector<std::string> names = codec::exrCompressionNames();
    if (std::find(names.begin(), names.end(), settings.exrCompression) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        return invalidInput("EXR compression: expected one of " + list + ", got '" +
                            excerpt(settings.exrCompression, 60) + "'");
    }
    return Ok{};
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

Status encodeAndWrite(const std::string& path, const Writer& w, const codec::Samples& s,
                      const EncodeSettings& settings) {
    // Checked here too: a library caller may fill the settings by hand.
    if (Status check = checkEncodeSettings(settings); !check) return check;
    codec::EncodeOptions options;
    options.pngCompression = settings.pngCompression;
    if (!settings.exrCompression.empty()) options.exrCompression = settings.exrCompression;
    options.exrZipLevel = settings.exrZipLevel;
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

Status checkSampleFormatFits(const std::string& path, SampleFormat requested,
                             const std::string& option) {
    if (requested == SampleFormat::Auto) return Ok{};
    const std::string ext = lowerExtension(path);
    using F = SampleFormat;
    std::vector<F> holds{F::U8};
    if (ext == ".png") holds = {F::U8, F::U16};
    if (ext == ".tif" || ext == ".tiff") holds = {F::U8, F::U16, F::Half, F::Float};
    if (ext == ".exr") holds = {F::Half, F::Float};
    if (ext == ".hdr") holds = {F::Half, F::Float};
    if (std::find(holds.begin(), holds.end(), requested) != holds.end()) return Ok{};
    std::string names;
    for (F f : holds)
        names.append(names.empty() ? "" : ", ").append(kSampleFormatNames[std::size_t(f)]);
    const std::string name(kSampleFormatNames[std::size_t(requested)]);
    const std::string holdsWhat = "a '" + ext + "' file holds " + names + " samples";
    if (option.empty()) return invalidInput(path + ": " + holdsWhat + ", not " + name);
    return invalidInput(path + ": " + option + " " + name + ": " + holdsWhat);
}

//! No format holds an image without pixels, and some encoders fail on one by crashing
//! (OpenImageIO's BMP writer divides by its zero size): refused before any encoder sees it.
Status checkHasPixels(const std::string& path, int width, int height) {
    if (width > 0 && height > 0) return Ok{};
    return invalidInput(path + ": nothing to write: the image is " + std::to_string(width) + "x" +
                        std::to_string(height));
}

Status writeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    // After a signal nothing more is encoded (a 4K encode takes a second): the job stops now.
    if (interrupted()) return interruptedError(path + " was not written");
    if (Status s = checkHasPixels(path, image.width(), image.height()); !s) return s;
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
    if (Status fits = checkSampleFormatFits(path, options.format); !fits) return fits;
    codec::Samples s;
    s.width = image.width();
    s.height = image.height();
    s.extras = extras;
    s.chosenCompression = !options.encode.exrCompression.empty();
    s.colorSpace = options.colorSpace;
    s.channels = channels;
    s.srgb = !isFloat && options.srgbEncode;
    const std::size_t pixels = image.pixelCount();
    // Encoded here, so the code values are flarekit's, not a library's. The sample buffers are
    // pixel memory (PixelAllocator): every element is written once, so none is cleared first.
    const auto encodeAs = [&](auto code, SampleType type, auto encode) {
        std::vector<decltype(code), PixelAllocator<decltype(code)>> codes(pixels *
                                                                          std::size_t(channels));
        const std::size_t width = std::size_t(image.width());
        const auto encodeRows = [&](std::size_t p0, std::size_t p1) {
            encode(image.data() + p0 * 4, p1 - p0, channels,
                   codes.data() + p0 * std::size_t(channels));
        };
        s.type = type;
        s.data = codes.data();
        if (writer->format != Format::Png) {
            forEachChunk(pixels, encodeRows);
            return encodeAndWrite(path, *writer, s, options.encode);
        }
        // The PNG encoder has the rows made band by band as it goes (beside zlib, not all first).
        s.fillRows = [&](int y0, int y1) {
            encodeRows(std::size_t(y0) * width, std::size_t(y1) * width);
        };
        return encodeAndWrite(path, *writer, s, options.encode);
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
        std::vector<std::uint16_t, PixelAllocator<std::uint16_t>> halves(pixels *
                                                                         std::size_t(channels));
        forEachChunk(pixels, [&](std::size_t p0, std::size_t p1) {
            floatsToHalf(image.data() + p0 * 4, p1 - p0, channels,
                         halves.data() + p0 * std::size_t(channels));
        });
        s.data = halves.data();
        return encodeAndWrite(path, *writer, s, options.encode);
    }
    if (writer->format == Format::Exr && allFinite(image)) {
        s.data = image.data();
        s.pixelStride = 4 * sizeof(float);
        return encodeAndWrite(path, *writer, s, options.encode);
    }
    std::vector<float, PixelAllocator<float>> linear(pixels * std::size_t(channels));
    forEachChunk(pixels, [&](std::size_t p0, std::size_t p1) {
        for (std::size_t p = p0; p < p1; ++p) {
            for (int c = 0; c < channels; ++c) {
                const float v = image.data()[p * 4 + std::size_t(c)];
                linear[p * std::size_t(channels) + std::size_t(c)] = std::isfinite(v) ? v : 0.f;
            }
        }
    });
    s.data = linear.data();
    return encodeAndWrite(path, *writer, s, options.encode);
}

Status writeImage8(const std::string& path, const Image8& image, const EncodeSettings& encode) {
    if (Status s = checkHasPixels(path, image.width, image.height); !s) return s;
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
    return encodeAndWrite(path, w, s, encode);
}

}  // namespace flarekit
