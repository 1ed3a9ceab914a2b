// SPDX-License-Identifier: Apache-2.0
// OpenEXR through its own C++ library, on its thread pool: reads land straight in flarekit's
// float RGBA image (each channel a strided slice of it) and writes take their slices from it.
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDeepScanLineInputPart.h>
#include <ImfDeepScanLineOutputPart.h>
#include <ImfDeepTiledInputPart.h>
#include <ImfDeepTiledOutputPart.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <ImfTiledInputPart.h>
#include <ImfTiledOutputPart.h>
#include <half.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/FirstLine.h"
#include "core/HalfFloat.h"
#include "core/Parallel.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"

namespace flarekit::codec {

namespace {

//! Bytes of one sample of channel c: 2 for half, 4 for float and uint.
std::size_t sampleBytes(const Imf::Channel& c) {
    return c.type == Imf::HALF ? 2 : 4;
}

//! OpenEXR decodes and encodes line blocks in parallel when its global pool has threads; one
//! per core, as OpenImageIO sets it.
void startThreadPool() {
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
    });
}

//! Rows per task where a read's pixels are converted and checked on every core: 8 rows of
//! 1920 pixels are 15,000 pixels, enough work to outweigh a task's start.
constexpr int kRowsPerTask = 8;

//! What an EXR read owes the rest of flarekit, on pixels [begin, end) of float RGBA: a grey
//! image's Y copied to G and B, then every NaN replaced by 0 and every infinity clamped to
//! +-65504 (sanitisedSample). Returns how many were replaced.
std::size_t finishExrPixels(float* begin, float* end, bool grey) {
    if (grey)
        for (float* d = begin; d < end; d += 4) d[1] = d[2] = d[0];
    // Looked for first with a test the compiler vectorises (a float is NaN or infinite when its
    // exponent bits are all ones), so a clean frame costs one read of its pixels.
    bool any = false;
    for (const float* d = begin; d < end; ++d) {
        std::uint32_t bits;
        std::memcpy(&bits, d, sizeof bits);
        any |= (bits & 0x7F800000u) == 0x7F800000u;
    }
    if (!any) return 0;
    std::size_t bad = 0;
    for (float* d = begin; d < end; ++d) {
        if (!std::isfinite(*d)) {
            *d = sanitisedSample(*d);
            ++bad;
        }
    }
    return bad;
}

//! finishExrPixels over the whole image, rows on every core: the read straight into floats.
std::size_t finishImage(Image& image, bool grey) {
    std::atomic<std::size_t> nonFinite{0};
    const std::size_t rowFloats = 4 * std::size_t(image.width());
    parallelFor(0, image.height(), kRowsPerTask, [&](int y0, int y1) {
        float* const begin = image.row(y0);
        nonFinite += finishExrPixels(begin, begin + std::size_t(y1 - y0) * rowFloats, grey);
    });
    return nonFinite;
}

//! Scanlines per chunk of each compression (OpenEXR's file layout): a chunk is decoded once per
//! readPixels call that touches it, so bands of rows start and end on chunk boundaries.
int chunkRows(Imf::Compression c) {
    switch (c) {
        case Imf::NO_COMPRESSION:
        case Imf::RLE_COMPRESSION:
        case Imf::ZIPS_COMPRESSION:
            return 1;
        case Imf::ZIP_COMPRESSION:
        case Imf::PXR24_COMPRESSION:
            return 16;
        case Imf::PIZ_COMPRESSION:
        case Imf::B44_COMPRESSION:
        case Imf::B44A_COMPRESSION:
        case Imf::DWAA_COMPRESSION:
            return 32;
        default:
            return 256;  // DWAB, and the most any compression uses
    }
}

//! Whether any of `count` halves is NaN or infinite (exponent bits all ones): the check of a
//! clean band, 8 halves per vector compare, before any float of it is looked at again.
bool anyNonFinite(const std::uint16_t* halves, std::size_t count) {
    unsigned any = 0;
    for (std::size_t i = 0; i < count; ++i) any |= unsigned((halves[i] & 0x7C00u) == 0x7C00u);
    return any != 0;
}

//! The read of a scanline file whose image channels are all half floats. OpenEXR copies each
//! band of rows, as halves, into a small buffer of interleaved RGBA halves; F16C converts the
//! band into the image while it is still in cache, and finishExrPixels runs on it there. Read
//! straight into floats, OpenEXR looks every sample up in a 256 KiB table, and the
//! non-finite scan then read the whole image again. `names`: the channel read into each RGBA
//! lane (R, G, B, A, or Y, -, -, A); one the file lacks is skipped. A band is about 128 rows (2 MiB
//! of halves at 1920 wide, a core's L2 here): several chunks for each of OpenEXR's threads per
//! call. Returns how many NaN and infinite values were replaced (finishExrPixels).
template <class File>
std::size_t readHalfInBands(File& file, const Imf::FrameBuffer& extras,
                            const std::vector<std::string>& names, bool hasAlpha, bool grey,
                            Image& image) {
    const Imath::Box2i window = file.header().dataWindow();
    const int width = image.width(), chunk = chunkRows(file.header().compression());
    const int band = std::max(chunk, 128 / chunk * chunk);
    const std::size_t rowHalves = 4 * std::size_t(width);
    std::vector<std::uint16_t> halves(rowHalves * std::size_t(std::min(band, image.height())));
    if (!hasAlpha) {  // OpenEXR fills a missing channel; here alpha is 1 (0x3C00) from the start
        for (std::size_t i = 3; i < halves.size(); i += 4) halves[i] = 0x3C00;
    }
    std::atomic<std::size_t> nonFinite{0};
    for (int y0 = window.min.y; y0 <= window.max.y; y0 += band) {
        const int y1 = std::min(window.max.y, y0 + band - 1);
        const Imath::Box2i rows(Imath::V2i(window.min.x, y0), Imath::V2i(window.max.x, y1));
        Imf::FrameBuffer frame = extras;
        for (std::size_t c = 0; c < names.size(); ++c) {
            if (!file.header().channels().findChannel(names[c]))
                continue;  // no such channel: alpha is preset
            frame.insert(names[c], Imf::Slice::Make(Imf::HALF, halves.data() + c, rows,
                                                    4 * sizeof(half), rowHalves * sizeof(half)));
        }
        file.setFrameBuffer(frame);
        file.readPixels(y0, y1);
        const int first = y0 - window.min.y;
        parallelFor(0, y1 - y0 + 1, kRowsPerTask, [&](int r0, int r1) {
            const std::uint16_t* const in = halves.data() + std::size_t(r0) * rowHalves;
            const std::size_t count = std::size_t(r1 - r0) * rowHalves;
            float* const begin = image.row(first + r0);
            halfsToFloats(in, count, begin);
            if (grey || anyNonFinite(in, count))
                nonFinite += finishExrPixels(begin, begin + count, grey);
        });
    }
    return nonFinite;
}

//! The image of `file` (a single-part file, or one part of a multi-part one).
template <class File>
Result<ExrRead> readExrImage(File& file, const std::string& path, const HeaderCheck& check) {
    {
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const Imf::ChannelList& channels = header.channels();
        int count = 0;
        bool subsampled = false;
        for (auto c = channels.begin(); c != channels.end(); ++c) {
            ++count;
            subsampled |= c.channel().xSampling != 1 || c.channel().ySampling != 1;
        }
        const bool rgb =
            channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        const bool grey = !rgb && channels.findChannel("Y") && !channels.findChannel("RY");
        if ((!rgb && !grey) || subsampled) return invalidInput(kUnsupportedLayout);
        // The channels read into the RGBA image; every other one is kept as an extra.
        const std::vector<std::string> read =
            rgb ? std::vector<std::string>{"R", "G", "B", "A"} : std::vector<std::string>{"Y", "A"};
        const auto isRead = [&](const std::string& name) {
            return std::find(read.begin(), read.end(), name) != read.end();
        };
        ExrRead out;
        out.header.width = int(std::min<long>(long(window.max.x) - window.min.x + 1, 1L << 30));
        out.header.height = int(std::min<long>(long(window.max.y) - window.min.y + 1, 1L << 30));
        out.header.channels = count;
        out.header.isFloat = true;
        out.header.decodeAs = SampleType::F32;
        out.header.format = "openexr";
        if (out.header.width < 1 || out.header.height < 1) {
            return invalidInput(path + ": image size " + std::to_string(out.header.width) + "x" +
                                std::to_string(out.header.height) +
                                ": expected width and height in [1, 32768]");
        }
        // The channels past RGBA (or Y, A) are read too, in their own types: counted before any
        // allocation, so a file of a thousand channels is refused by the memory check.
        for (auto c = channels.begin(); c != channels.end(); ++c) {
            if (!isRead(c.name()))
                out.header.extraBytesPerPixel += double(sampleBytes(c.channel()));
        }
        if (Status s = check(out.header); !s) return s.error();
        out.image = Image(out.header.width, out.header.height);
        out.hasAlpha = channels.findChannel("A") != nullptr;
        out.allHalf = true;
        for (const std::string& name : read) {
            const Imf::Channel* c = channels.findChannel(name);
            if (c) out.allHalf = out.allHalf && c->type == Imf::HALF;
        }
        // Every other channel is read too, in its own type, for the write to give back.
        auto extras = std::make_shared<ExrExtras>();
        extras->header = header;
        const Imf::Channel* red = channels.findChannel(rgb ? "R" : "Y");
        extras->rgbHalf = red && red->type == Imf::HALF;
        for (auto c = channels.begin(); c != channels.end(); ++c) {
            if (isRead(c.name())) continue;
            ExrExtraChannel extra{c.name(), c.channel(), {}};
            extra.pixels.resize(sampleBytes(c.channel()) * std::size_t(out.header.width) *
                                std::size_t(out.header.height));
            extras->channels.push_back(std::move(extra));
        }
        Imf::FrameBuffer frame;
        for (ExrExtraChannel& e : extras->channels) {
            const std::size_t size = sampleBytes(e.channel);
            frame.insert(e.name, Imf::Slice::Make(e.channel.type, e.pixels.data(), window, size,
                                                  size * std::size_t(out.header.width)));
        }
        out.extras = std::move(extras);
        if (out.allHalf && !header.hasTileDescription()) {
            const std::vector<std::string> lanes =
                rgb ? read : std::vector<std::string>{"Y", "", "", "A"};
            out.nonFinite = readHalfInBands(file, frame, lanes, out.hasAlpha, grey, out.image);
            return out;
        }
        // Slices into the RGBA floats; a channel the file lacks is filled (alpha with 1).
        char* base = reinterpret_cast<char*>(out.image.data());
        const std::size_t xStride = 4 * sizeof(float),
                          yStride = xStride * std::size_t(out.header.width);
        auto slice = [&](const char* name, int offset, double fill) {
            frame.insert(name, Imf::Slice::Make(Imf::FLOAT, base + offset * sizeof(float), window,
                                                xStride, yStride, 1, 1, fill));
        };
        if (rgb) {
            slice("R", 0, 0.0);
            slice("G", 1, 0.0);
            slice("B", 2, 0.0);
        } else {
            slice("Y", 0, 0.0);
        }
        slice("A", 3, 1.0);
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        out.nonFinite = finishImage(out.image, grey);
        return out;
    }
}

//! A part's name as a user gives it: its name attribute, else its index.
std::string partName(const Imf::Header& header, int index) {
    return header.hasName() ? header.name() : std::to_string(index);
}

//! The index of the part `wanted` names (a name, or an index), or the error listing the parts.
Result<int> choosePart(const Imf::MultiPartInputFile& file, const std::string& wanted,
                       const std::string& path) {
    std::string list;
    for (int i = 0; i < file.parts(); ++i) {
        const std::string name = partName(file.header(i), i);
        if (name == wanted || std::to_string(i) == wanted) return i;
        list += (i ? ", " : "") + std::to_string(i) + " '" + name + "'";
    }
    return invalidInput("--part " + excerpt(wanted, 60) + ": " + path + " has no such part (" +
                        std::to_string(file.parts()) + ": " + excerpt(list, 400) + ")");
}

}  // namespace

Result<ExrRead> readExr(const std::string& path, const HeaderCheck& check, const std::string& part,
                        std::vector<std::string>* partNames) {
    startThreadPool();
    try {
        Imf::MultiPartInputFile parts(path.c_str());
        if (partNames)
            for (int i = 0; i < parts.parts(); ++i)
                partNames->push_back(partName(parts.header(i), i));
        if (parts.parts() == 1 &&
            (part.empty() || part == "0" || part == partName(parts.header(0), 0))) {
            Imf::InputFile file(path.c_str());
            return readExrImage(file, path, check);
        }
        int chosen = 0;
        if (!part.empty()) {
            auto index = choosePart(parts, part, path);
            if (!index) return index.error();
            chosen = *index;
        }
        const std::string type = parts.header(chosen).type();
        if (type != Imf::SCANLINEIMAGE && type != Imf::TILEDIMAGE)
            return invalidInput(path + ": part " + partName(parts.header(chosen), chosen) +
                                " is deep (" + type + "); flarekit flares a flat image part");
        Imf::InputPart input(parts, chosen);
        auto read = readExrImage(input, path, check);
        if (!read || parts.parts() == 1) return read;
        auto kept = std::make_shared<ExrParts>();
        kept->source = path;
        kept->chosen = chosen;
        for (int i = 0; i < parts.parts(); ++i) kept->headers.push_back(parts.header(i));
        auto extras = std::make_shared<ExrExtras>(*read->extras);
        extras->parts = std::move(kept);
        read->extras = std::move(extras);
        return read;
    } catch (const std::exception& e) {
        return invalidInput(path + ": cannot decode image: " + excerpt(firstLine(e.what()), 200));
    }
}

namespace {

//! OpenEXR's compressions by the names its documentation and tools use.
const std::pair<const char*, Imf::Compression> kExrCompressions[] = {
    {"none", Imf::NO_COMPRESSION},   {"rle", Imf::RLE_COMPRESSION},
    {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION},
    {"piz", Imf::PIZ_COMPRESSION},   {"pxr24", Imf::PXR24_COMPRESSION},
    {"b44", Imf::B44_COMPRESSION},   {"b44a", Imf::B44A_COMPRESSION},
    {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION},
};

}  // namespace

std::vector<std::string> exrCompressionNames() {
    std::vector<std::string> names;
    for (const auto& c : kExrCompressions) names.emplace_back(c.first);
    return names;
}

namespace {

//! The encoded file in memory; OpenEXR seeks back to write its line offset table. Its room is
//! reserved up front (`expected`: the raw size, an upper bound for all but incompressible
//! data), so the file is never moved as it grows; pages past what is written are never touched.
class MemoryStream : public Imf::OStream {
  public:
    explicit MemoryStream(std::size_t expected) : Imf::OStream("memory") {
        m_bytes.reserve(expected);
    }
    void write(const char c[], int n) override {
        if (m_at > m_bytes.size()) m_bytes.resize(m_at);
        const std::size_t end = m_at + std::size_t(n);
        const std::size_t inside = std::min(end, m_bytes.size()) - m_at;
        if (inside > 0) std::memcpy(m_bytes.data() + m_at, c, inside);  // the offset table
        m_bytes.insert(m_bytes.end(), c + inside, c + n);               // past the end
        m_at = end;
    }
    uint64_t tellp() override { return m_at; }
    void seekp(uint64_t pos) override { m_at = std::size_t(pos); }
    std::vector<unsigned char>& bytes() { return m_bytes; }

  private:
    std::vector<unsigned char> m_bytes;
    std::size_t m_at = 0;
};

}  // namespace

namespace {

//! The primaries and white point (CIE 1931 xy) of the colour spaces whose names say them: ACEScg
//! (AP1) and ACES2065-1 (AP0) with the ACES white, from SMPTE ST 2065-1 and the Academy's
//! S-2014-004; Rec.709 and sRGB with D65, from ITU-R BT.709-6. Matched without case, spaces,
//! hyphens or underscores, so "ACES - ACEScg", "acescg" and "lin_ap1" are one.
std::optional<Imf::Chromaticities> knownChromaticities(const std::string& name) {
    std::string key;
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c)))
            key += char(std::tolower(static_cast<unsigned char>(c)));
    const auto ends = [&](const char* tail) {
        const std::string t(tail);
        return key.size() >= t.size() && key.compare(key.size() - t.size(), t.size(), t) == 0;
    };
    const Imath::V2f acesWhite(0.32168f, 0.33767f), d65(0.3127f, 0.3290f);
    if (ends("acescg") || ends("linap1") || ends("ap1"))
        return Imf::Chromaticities({0.713f, 0.293f}, {0.165f, 0.830f}, {0.128f, 0.044f}, acesWhite);
    if (ends("aces20651") || ends("linap0") || ends("ap0"))
        return Imf::Chromaticities({0.7347f, 0.2653f}, {0.0f, 1.0f}, {0.0001f, -0.077f}, acesWhite);
    if (ends("rec709") || ends("srgb") || ends("bt709"))
        return Imf::Chromaticities({0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, d65);
    return std::nullopt;
}

//! Names the file's colour space as OpenImageIO does (oiio:ColorSpace) and, where its primaries
//! are known, writes them as the standard chromaticities attribute.
void tagColorSpace(Imf::Header& header, const std::string& name) {
    header.insert("oiio:ColorSpace", Imf::StringAttribute(name));
    if (const auto c = knownChromaticities(name)) Imf::addChromaticities(header, *c);
}

}  // namespace

namespace {
//! A multi-part file: the flared part written from `frame` in its place among the input's parts,
//! every other part copied from the input chunk for chunk (no decode, so bit for bit), whatever
//! its kind (scanline, tiled, deep).
void writeWithOtherParts(Imf::OStream& memory, Imf::Header flared, const Imf::FrameBuffer& frame,
                         int height, const ExrParts& parts) {
    std::vector<Imf::Header> headers = parts.headers;
    const Imf::Header& original = parts.headers[std::size_t(parts.chosen)];
    flared.setName(original.name());  // every part of a multi-part file is named
    flared.setType(Imf::SCANLINEIMAGE);
    headers[std::size_t(parts.chosen)] = flared;
    // Shared attributes (display window, pixel aspect, time code, chromaticities) are the first
    // part's in every part, as the format requires.
    Imf::MultiPartOutputFile out(memory, headers.data(), int(headers.size()), true);
    Imf::MultiPartInputFile in(parts.source.c_str());
    for (int i = 0; i < int(headers.size()); ++i) {
        const std::string type = headers[std::size_t(i)].type();
        if (i == parts.chosen) {
            Imf::OutputPart part(out, i);
            part.setFrameBuffer(frame);
            part.writePixels(height);
        } else if (type == Imf::TILEDIMAGE) {
            Imf::TiledInputPart from(in, i);
            Imf::TiledOutputPart(out, i).copyPixels(from);
        } else if (type == Imf::DEEPSCANLINE) {
            Imf::DeepScanLineInputPart from(in, i);
            Imf::DeepScanLineOutputPart(out, i).copyPixels(from);
        } else if (type == Imf::DEEPTILE) {
            Imf::DeepTiledInputPart from(in, i);
            Imf::DeepTiledOutputPart(out, i).copyPixels(from);
        } else {
            Imf::InputPart from(in, i);
            Imf::OutputPart(out, i).copyPixels(from);
        }
    }
}
}  // namespace

Result<std::vector<unsigned char>> encodeExr(const Samples& s, const EncodeOptions& options) {
    startThreadPool();
    if (s.type != SampleType::F32) return internalError("EXR takes float or half samples");
    try {
        const auto named =
            std::find_if(std::begin(kExrCompressions), std::end(kExrCompressions),
                         [&](const auto& c) { return options.exrCompression == c.first; });
        if (named == std::end(kExrCompressions))
            return internalError("unknown EXR compression '" + options.exrCompression + "'");
        Imf::Compression compression = named->second;
        Imf::Header header(s.width, s.height, 1.f, Imath::V2f(0, 0), 1.f, Imf::INCREASING_Y,
                           compression);
        const ExrExtras* extras = s.extras;
        if (extras) {
            // The input's header, less what the written file decides itself: its windows,
            // attributes and (unless one was chosen) compression.
            const Imf::Header& in = extras->header;
            if (!s.chosenCompression) compression = in.compression();
            header = Imf::Header(in.displayWindow(), in.dataWindow(), in.pixelAspectRatio(),
                                 in.screenWindowCenter(), in.screenWindowWidth(), Imf::INCREASING_Y,
                                 compression);
            static const char* const kStructural[] = {"channels",
                                                      "compression",
                                                      "dataWindow",
                                                      "displayWindow",
                                                      "lineOrder",
                                                      "pixelAspectRatio",
                                                      "screenWindowCenter",
                                                      "screenWindowWidth",
                                                      "tiles",
                                                      "type",
                                                      "chunkCount",
                                                      "version",
                                                      "maxSamplesPerPixel",
                                                      "software"};
            for (auto a = in.begin(); a != in.end(); ++a) {
                if (std::find_if(std::begin(kStructural), std::end(kStructural),
                                 [&](const char* k) { return std::strcmp(k, a.name()) == 0; }) ==
                    std::end(kStructural))
                    header.insert(a.name(), a.attribute());
            }
        }
        header.insert("software", Imf::StringAttribute("flarekit"));
        if (!s.colorSpace.empty()) tagColorSpace(header, s.colorSpace);
        header.zipCompressionLevel() = options.exrZipLevel;
        const Imath::Box2i window = header.dataWindow();
        // OpenEXR's writer takes samples of the file's own type: half samples come packed
        // (converted by the caller), floats straight from the image with its stride.
        const Imf::PixelType type = s.half ? Imf::HALF : Imf::FLOAT;
        const std::size_t sample = s.half ? sizeof(half) : sizeof(float);
        const char* names[] = {"R", "G", "B", "A"};
        const std::size_t xStride =
            s.pixelStride ? s.pixelStride : std::size_t(s.channels) * sample;
        const std::size_t yStride = xStride * std::size_t(s.width);
        Imf::FrameBuffer frame;
        for (int c = 0; c < s.channels; ++c) {
            header.channels().insert(names[c], Imf::Channel(type));
            frame.insert(names[c],
                         Imf::Slice::Make(type,
                                          const_cast<char*>(static_cast<const char*>(s.data)) +
                                              sample * std::size_t(c),
                                          window, xStride, yStride));
        }
        if (extras) {
            for (const ExrExtraChannel& e : extras->channels) {
                const std::size_t size = sampleBytes(e.channel);
                header.channels().insert(e.name, e.channel);
                frame.insert(e.name,
                             Imf::Slice::Make(e.channel.type, const_cast<char*>(e.pixels.data()),
                                              window, size, size * std::size_t(s.width)));
            }
        }
        std::size_t rawBytes = std::size_t(s.channels) * sample;
        if (extras)
            for (const ExrExtraChannel& e : extras->channels) rawBytes += sampleBytes(e.channel);
        MemoryStream memory(rawBytes * std::size_t(s.width) * std::size_t(s.height) + 65536);
        if (extras && extras->parts) {
            writeWithOtherParts(memory, header, frame, s.height, *extras->parts);
        } else {
            Imf::OutputFile file(memory, header);
            file.setFrameBuffer(frame);
            file.writePixels(s.height);
        }
        return std::move(memory.bytes());
    } catch (const std::exception& e) {
        return ioError(std::string("cannot encode EXR: ") + firstLine(e.what()));
    }
}

}  // namespace flarekit::codec
