// SPDX-License-Identifier: Apache-2.0
// OpenEXR writing through its own C++ library, on its thread pool: the samples as slices, the
// input's header, channels and other parts given back, in bands that a signal can stop.
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDeepScanLineInputPart.h>
#include <ImfDeepScanLineOutputPart.h>
#include <ImfDeepTiledInputPart.h>
#include <ImfDeepTiledOutputPart.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfTiledInputPart.h>
#include <ImfTiledOutputFile.h>
#include <ImfTiledOutputPart.h>
#include <half.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "core/FirstLine.h"
#include "core/Interrupt.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"
#include "core/codecs/ExrShared.h"

namespace flarekit::codec {

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
//! Rows per band of a scanline write: the interrupt is polled between bands, so a signal during
//! a 4K float encode (about a second on 2 cores) stops it within a few milliseconds.
constexpr int kWriteBandRows = 128;

//! `file`'s scanlines (an OutputFile or OutputPart with its frame buffer set) in bands, false
//! when a signal stopped it.
template <class Output>
bool writeScanlinesInBands(Output& file, int height) {
    for (int y = 0; y < height; y += kWriteBandRows) {
        if (interrupted()) return false;
        file.writePixels(std::min(kWriteBandRows, height - y));
    }
    return true;
}

//! `file`'s tiles (a TiledOutputFile or TiledOutputPart) a row of tiles at a time, false when a
//! signal stopped it.
template <class Output>
bool writeTilesInRows(Output& file) {
    for (int ty = 0; ty < file.numYTiles(); ++ty) {
        if (interrupted()) return false;
        file.writeTiles(0, file.numXTiles() - 1, ty, ty);
    }
    return true;
}

//! A multi-part file: the flared part written from `frame` in its place among the input's parts,
//! every other part copied from the input chunk for chunk (no decode, so bit for bit), whatever
//! its kind (scanline, tiled, deep).
bool writeWithOtherParts(Imf::OStream& memory, Imf::Header flared, const Imf::FrameBuffer& frame,
                         int height, const ExrParts& parts) {
    std::vector<Imf::Header> headers = parts.headers;
    const Imf::Header& original = parts.headers[std::size_t(parts.chosen)];
    flared.setName(original.name());  // every part of a multi-part file is named
    const bool tiled = flared.hasTileDescription();
    flared.setType(tiled ? Imf::TILEDIMAGE : Imf::SCANLINEIMAGE);
    headers[std::size_t(parts.chosen)] = flared;
    // Shared attributes (display window, pixel aspect, time code, chromaticities) are the first
    // part's in every part, as the format requires.
    Imf::MultiPartOutputFile out(memory, headers.data(), int(headers.size()), true);
    Imf::MultiPartInputFile in(parts.source.c_str());
    for (int i = 0; i < int(headers.size()); ++i) {
        const std::string type = headers[std::size_t(i)].type();
        if (i == parts.chosen && tiled) {
            Imf::TiledOutputPart part(out, i);
            part.setFrameBuffer(frame);
            if (!writeTilesInRows(part)) return false;
        } else if (i == parts.chosen) {
            Imf::OutputPart part(out, i);
            part.setFrameBuffer(frame);
            if (!writeScanlinesInBands(part, height)) return false;
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
    return true;
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
            // A tiled input stays tiled, in its tile size (one level: the flared image has no
            // mipmaps of its own).
            if (in.hasTileDescription()) {
                Imf::TileDescription tiles = in.tileDescription();
                tiles.mode = Imf::ONE_LEVEL;
                header.setTileDescription(tiles);
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
        // A layer-named part (diffuse.R, ...) keeps its names.
        const std::string layer = extras ? extras->layer : "";
        const std::string names[] = {layer + "R", layer + "G", layer + "B", layer + "A"};
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
        bool written = false;
        if (extras && extras->parts) {
            written = writeWithOtherParts(memory, header, frame, s.height, *extras->parts);
        } else if (header.hasTileDescription()) {
            Imf::TiledOutputFile file(memory, header);
            file.setFrameBuffer(frame);
            written = writeTilesInRows(file);
        } else {
            Imf::OutputFile file(memory, header);
            file.setFrameBuffer(frame);
            written = writeScanlinesInBands(file, s.height);
        }
        if (!written) return interruptedError("an EXR encode was stopped");
        return std::move(memory.bytes());
    } catch (const std::exception& e) {
        return ioError(std::string("cannot encode EXR: ") + firstLine(e.what()));
    }
}

}  // namespace flarekit::codec
