// SPDX-License-Identifier: Apache-2.0
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <span>

#include "core/HalfFloat.h"
#include "core/ImageIOShared.h"
#include "core/Interrupt.h"
#include "core/LibraryNoise.h"
#include "core/SafeWrite.h"
#include "core/codecs/ExrExtras.h"
#include "flarekit/Limits.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/Job.h"
#include "job/PixelLoad.h"
#include "job/ReadClock.h"

namespace flarekit {

namespace {
//! The warning of an image whose non-finite samples were replaced (none: silent).
void warnNonFinite(const std::string& name, std::size_t count, const JobEvents& events) {
    if (count == 0) return;
    events.warn(name + ": " + std::to_string(count) +
                " NaN/Inf values: NaN read as 0, infinities clamped to +-65504 (the largest half "
                "float)");
}
}  // namespace

namespace job_detail {
namespace {
std::atomic<double> g_readSeconds{0};
}
void addReadSeconds(double seconds) {
    g_readSeconds += seconds;
}
double takeReadSeconds() {
    return g_readSeconds.exchange(0);
}

Result<LoadedImage> loadedFromPixels(PixelInput&& input, const JobMemory& job,
                                     const JobEvents& events) {
    const double pixels = double(input.image.pixelCount());
    if (pixels == 0) return invalidInput(input.name + ": an image without pixels (0 x 0)");
    if (Status s = checkMemory(input.name, job.bytesPerPixel * pixels + job.fixedBytes, job.detail);
        !s)
        return s.error();
    LoadedImage loaded;
    // As the file readers do (sanitisedSample): NaN as 0, infinities as the largest half.
    for (float& v : std::span(input.image.data(), input.image.pixelCount() * 4)) {
        if (std::isfinite(v)) continue;
        v = sanitisedSample(v);
        ++loaded.nonFinite;
    }
    warnNonFinite(input.name, loaded.nonFinite, events);
    loaded.image = std::move(input.image);
    loaded.fileChannels = input.hasAlpha ? 4 : 3;
    loaded.hasAlpha = input.hasAlpha;
    loaded.wasFloat = !input.displayReferred;
    return loaded;
}

}  // namespace job_detail

Result<LoadedImage> readJobInput(const std::string& path, const JobMemory& job,
                                 const JobEvents& events, const ReadOptions& read) {
    const auto start = std::chrono::steady_clock::now();
    auto loaded = [&] {
        LibraryNoiseFilter filter;
        return readImage(path, job, read);
    }();
    job_detail::addReadSeconds(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!loaded) return loaded.error();
    if (loaded->droppedChannels > 0) {
        return invalidInput(
            path + ": " + std::to_string(loaded->fileChannels) +
            " channels; flarekit reads 1 to 4 (grey, grey+alpha, RGB, RGBA): split the others off "
            "first, e.g. oiiotool IN --ch R,G,B,A -o rgba.exr");
    }
    if (!loaded->decoderWarning.empty())
        events.warn(path + ": " + loaded->decoderWarning + " (read on; check the file)");
    warnNonFinite(path, loaded->nonFinite, events);
    return loaded;
}

Status checkPartsFit(const LoadedImage& loaded, const std::string& in, const std::string& out) {
    if (loaded.exrParts.empty() || imageio::lowerExtension(out) == ".exr") return Ok{};
    std::string parts;
    for (const std::string& name : loaded.exrParts) parts += (parts.empty() ? "" : ", ") + name;
    return invalidInput(in + ": a multi-part EXR (" + std::to_string(loaded.exrParts.size()) +
                        " parts: " + parts +
                        "); its other parts go only to an EXR output, not to " + out +
                        ": write .exr (--part NAME picks the part flared)");
}

std::shared_ptr<const ExrExtras> keptExtras(const LoadedImage& loaded, const std::string& in,
                                            const std::string& out, const JobEvents& events) {
    if (!loaded.exrExtras) return nullptr;
    if (imageio::lowerExtension(out) != ".exr" && loaded.extraChannels > 0)
        events.warn(in + ": its " + std::to_string(loaded.extraChannels) +
                    " channel(s) past RGBA go only to an EXR output, not to " + out);
    return loaded.exrExtras;
}

std::shared_ptr<const ExrExtras> withLayerChannels(std::shared_ptr<const ExrExtras> extras,
                                                   const std::vector<NamedLayer>& layers) {
    if (layers.empty()) return extras;
    const Image& first = *layers.front().second;
    std::shared_ptr<ExrExtras> out;
    if (extras) {
        out = std::make_shared<ExrExtras>(*extras);
        // The passes are the same values `--layers DIR` writes losslessly: a lossy compression
        // of the input (DWAA/DWAB, B44/B44A, PXR24's 24-bit floats) would change them by up to
        // 2%, so the file is ZIP unless --exr-compression names one (which then wins).
        const Imf::Compression c = out->header.compression();
        if (c == Imf::DWAA_COMPRESSION || c == Imf::DWAB_COMPRESSION || c == Imf::B44_COMPRESSION ||
            c == Imf::B44A_COMPRESSION || c == Imf::PXR24_COMPRESSION)
            out->header.compression() = Imf::ZIP_COMPRESSION;
    } else {
        // No EXR input: a header of the image's size, with flarekit's own defaults (half
        // colour, PIZ) for the rest of the file.
        out = std::make_shared<ExrExtras>();
        out->header = Imf::Header(first.width(), first.height());
        out->header.compression() = Imf::PIZ_COMPRESSION;
    }
    for (const auto& [name, image] : layers) {
        const std::size_t pixels = image->pixelCount();
        for (int c = 0; c < 3; ++c) {
            ExrExtraChannel channel{name + "." + "RGB" [c], Imf::Channel(Imf::FLOAT), {}};
            channel.pixels.resize(pixels * sizeof(float));
            auto* dst = reinterpret_cast<float*>(channel.pixels.data());
            for (std::size_t i = 0; i < pixels; ++i) dst[i] = image->data()[4 * i + std::size_t(c)];
            out->channels.push_back(std::move(channel));
        }
    }
    return out;
}

Status checkLayersFit(bool layersInOutput, const std::string& out) {
    if (!layersInOutput || imageio::lowerExtension(out) == ".exr") return Ok{};
    return invalidInput("--layers-in-output: the passes become channels of an EXR output, not of " +
                        out + " (write .exr, or --layers DIR for files of their own)");
}

Status checkLightCoordinates(Point at, const std::string& option) {
    if (std::abs(double(at.x)) <= kMaxLightCoordinate &&
        std::abs(double(at.y)) <= kMaxLightCoordinate)
        return Ok{};
    char line[200];
    std::snprintf(line, sizeof line, "%s %g,%g: expected pixel coordinates from -%.0f to %.0f",
                  option.c_str(), double(at.x), double(at.y), kMaxLightCoordinate,
                  kMaxLightCoordinate);
    return invalidInput(line);
}

Error cancelledError(const std::string& what) {
    // A signal names itself ("interrupted by SIGTERM: ..."); a front end's cancel does not.
    if (interrupted()) return interruptedError(what);
    return {ErrorCode::Interrupted, "cancelled: " + what};
}

Status writeImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work) {
    if (Status s = checkOutputPath(out); !s) return s;
    auto result = work();
    if (!result) return result.error();
    return writeImage(out, result->image, result->options);
}

std::optional<ToneOperator> toneOperatorNamed(const std::string& name) {
    for (std::size_t i = 0; i < std::size(kToneOperatorNames); ++i)
        if (kToneOperatorNames[i] == name) return ToneOperator(i);
    return std::nullopt;
}

ToneOperator defaultDisplayCurve(bool hdrInput, const std::string& out, SampleFormat requested) {
    // No file (an in-memory job's result) is float, as an EXR is.
    if (out.empty()) return ToneOperator::None;
    return hdrInput && !isFloatFormat(outputSampleFormat(out, requested)) ? ToneOperator::Filmic
                                                                          : ToneOperator::None;
}

}  // namespace flarekit
