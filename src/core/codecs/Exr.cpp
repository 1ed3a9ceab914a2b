// SPDX-License-Identifier: Apache-2.0
// OpenEXR reading through its own C++ library, on its thread pool: reads land straight in
// flarekit's float RGBA image (each channel a strided slice of it). A multi-part file's part is
// chosen by --part's rule and the parts copied to the output are checked to decode. Writing:
// ExrWrite.cpp.
#include <ImfChannelList.h>
#include <ImfCheckFile.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfPartType.h>
#include <ImfThreading.h>
#include <ImfTiledInputPart.h>
#include <half.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <vector>

#include "core/FirstLine.h"
#include "core/HalfFloat.h"
#include "core/Interrupt.h"
#include "core/Parallel.h"
#include "core/codecs/Codecs.h"
#include "core/codecs/ExrExtras.h"
#include "core/codecs/ExrShared.h"

namespace flarekit::codec {

namespace {

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

//! The prefix of the colour channels: "" for R, G, B; "diffuse." for a part or file whose only
//! colour is one layer's diffuse.R, diffuse.G, diffuse.B (as Nuke writes a layer to a part).
//! Several such layers and no plain R, G, B: "" (which one is the image is not for flarekit to
//! guess; the read refuses).
std::string colourLayer(const Imf::ChannelList& channels) {
    if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B"))
        return "";
    std::string found;
    for (auto c = channels.begin(); c != channels.end(); ++c) {
        const std::string name = c.name();
        if (name.size() < 3 || name.compare(name.size() - 2, 2, ".R") != 0) continue;
        const std::string prefix = name.substr(0, name.size() - 1);
        if (!channels.findChannel(prefix + "G") || !channels.findChannel(prefix + "B")) continue;
        if (!found.empty()) return "";
        found = prefix;
    }
    return found;
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
        const std::string layer = colourLayer(channels);
        const bool rgb = channels.findChannel(layer + "R") && channels.findChannel(layer + "G") &&
                         channels.findChannel(layer + "B");
        const bool grey = !rgb && channels.findChannel("Y") && !channels.findChannel("RY");
        if ((!rgb && !grey) || subsampled) return invalidInput(kUnsupportedLayout);
        // The channels read into the RGBA image; every other one is kept as an extra.
        const std::vector<std::string> read =
            rgb ? std::vector<std::string>{layer + "R", layer + "G", layer + "B", layer + "A"}
                : std::vector<std::string>{"Y", "A"};
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
        out.hasAlpha = channels.findChannel(read.back()) != nullptr;
        out.allHalf = true;
        for (const std::string& name : read) {
            const Imf::Channel* c = channels.findChannel(name);
            if (c) out.allHalf = out.allHalf && c->type == Imf::HALF;
        }
        // Every other channel is read too, in its own type, for the write to give back.
        auto extras = std::make_shared<ExrExtras>();
        extras->header = header;
        extras->layer = layer;
        const Imf::Channel* red = channels.findChannel(read.front());
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
        auto slice = [&](const std::string& name, int offset, double fill) {
            frame.insert(name, Imf::Slice::Make(Imf::FLOAT, base + offset * sizeof(float), window,
                                                xStride, yStride, 1, 1, fill));
        };
        if (rgb) {
            for (int c = 0; c < 3; ++c) slice(read[std::size_t(c)], c, 0.0);
        } else {
            slice("Y", 0, 0.0);
        }
        slice(read.back(), 3, 1.0);
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

//! `wanted` as a part index: "#N" always, plain digits only when no part has that name.
std::optional<int> partIndexOf(const std::string& wanted) {
    const std::string digits = wanted.size() > 1 && wanted[0] == '#' ? wanted.substr(1) : wanted;
    if (digits.empty() || digits.size() > 6 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return std::stoi(digits);
}

//! The index of the part `wanted` names, or the error listing the parts. A name that matches
//! wins (parts named "1" and "0" are found by name); an index is used only when no part has that
//! name, and "#N" is always the index.
Result<int> choosePart(const Imf::MultiPartInputFile& file, const std::string& wanted,
                       const std::string& path) {
    std::string list;
    for (int i = 0; i < file.parts(); ++i) {
        const std::string name = partName(file.header(i), i);
        if (name == wanted && wanted[0] != '#') return i;
        list += (i ? ", " : "") + std::to_string(i) + " '" + name + "'";
    }
    if (const auto index = partIndexOf(wanted); index && *index < file.parts()) return *index;
    return invalidInput("--part " + excerpt(wanted, 60) + ": " + path + " has no such part (" +
                        std::to_string(file.parts()) + ": " + excerpt(list, 400) + ")");
}

//! A slice of `channel` into `scratch` for the rows or tile `box`: each band or tile lands at
//! the start of the scratch buffer (OpenEXR addresses a slice by absolute pixel coordinates).
void insertScratch(Imf::FrameBuffer& frame, const char* name, const Imath::Box2i& box,
                   std::vector<float>& scratch) {
    const std::size_t width = std::size_t(box.max.x - box.min.x + 1);
    scratch.resize(width * std::size_t(box.max.y - box.min.y + 1));
    frame.insert(name, Imf::Slice::Make(Imf::FLOAT, scratch.data(), box, sizeof(float),
                                        width * sizeof(float)));
}

//! Decodes every chunk of a flat part once (a band of rows or a tile at a time, into a scratch
//! buffer), so a chunk that does not decompress is found before a copy carries it out. One
//! channel is enough: a chunk is decompressed whole whichever channels are asked for.
bool decodeFlatPart(Imf::MultiPartInputFile& file, int index) {
    const Imf::Header& header = file.header(index);
    const char* channel = nullptr;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c)
        if (c.channel().xSampling == 1 && c.channel().ySampling == 1) channel = c.name();
    if (!channel) return false;  // only subsampled channels: left to OpenEXR's file check
    std::vector<float> scratch;
    if (header.type() == Imf::TILEDIMAGE) {
        Imf::TiledInputPart part(file, index);
        for (int ly = 0; ly < part.numYLevels(); ++ly)
            for (int lx = 0; lx < part.numXLevels(); ++lx) {
                if (!part.isValidLevel(lx, ly)) continue;
                for (int ty = 0; ty < part.numYTiles(ly); ++ty)
                    for (int tx = 0; tx < part.numXTiles(lx); ++tx) {
                        Imf::FrameBuffer frame;
                        insertScratch(frame, channel, part.dataWindowForTile(tx, ty, lx, ly),
                                      scratch);
                        part.setFrameBuffer(frame);
                        part.readTile(tx, ty, lx, ly);
                    }
            }
        return true;
    }
    Imf::InputPart part(file, index);
    const Imath::Box2i window = header.dataWindow();
    const int band = 64;  // rows per read: a whole number of chunks of every compression
    for (int y0 = window.min.y; y0 <= window.max.y; y0 += band) {
        const int y1 = std::min(window.max.y, y0 + band - 1);
        Imf::FrameBuffer frame;
        insertScratch(frame, channel, Imath::Box2i({window.min.x, y0}, {window.max.x, y1}),
                      scratch);
        part.setFrameBuffer(frame);
        part.readPixels(y0, y1);
    }
    return true;
}

//! Every part that goes to the output chunk for chunk decodes: each flat part decoded once
//! (naming the corrupt one), deep parts and parts of subsampled channels only by OpenEXR's own
//! file check (which reads the whole file, so only when there are any). The part flared was decoded
//! by the read itself. One line naming the file and the part; never a file that fails to open.
Status checkCopiedParts(const std::string& path, Imf::MultiPartInputFile& file, int chosen) {
    std::string others;  // the parts left to the file check
    for (int i = 0; i < file.parts(); ++i) {
        if (i == chosen) continue;
        const std::string type = file.header(i).type();
        // Appended, not "literal" + std::string: GCC 12 warns falsely (-Wrestrict) on the latter.
        std::string name(1, '\'');
        name.append(excerpt(partName(file.header(i), i), 60)).append(1, '\'');
        bool decoded = false;
        try {
            if (type == Imf::SCANLINEIMAGE || type == Imf::TILEDIMAGE)
                decoded = decodeFlatPart(file, i);
        } catch (const std::exception& e) {
            return invalidInput(path + ": part " + name + " (copied unchanged to the output) " +
                                "does not decode: " + excerpt(firstLine(e.what()), 200));
        }
        if (!decoded) others.append(others.empty() ? "" : ", ").append(name);
    }
    if (others.empty() || !Imf::checkOpenEXRFile(path.c_str())) return Ok{};
    return invalidInput(path + ": OpenEXR's file check fails on it (its parts " + others +
                        " are copied unchanged); a copy would not open");
}

//! A part flarekit cannot flare: one line naming the file, the part, its channels and what it
//! reads (OpenImageIO reads single-part files, not one part of many).
Error unsupportedPart(const std::string& path, const Imf::Header& header, int index) {
    std::string list;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c)
        list.append(list.empty() ? "" : ",").append(c.name());
    // Appended, not "literal" + std::string: GCC 12 warns falsely (-Wrestrict) on the latter.
    std::string line = path;
    line.append(": part '")
        .append(excerpt(partName(header, index), 60))
        .append("' has channels ")
        .append(excerpt(list, 200))
        .append("; flarekit flares R,G,B(,A), one layer's NAME.R,G,B(,A) or Y(,A), unsubsampled");
    return invalidInput(line);
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
        const Imf::Header& first = parts.header(0);
        const std::string firstType = first.hasType() ? first.type() : Imf::SCANLINEIMAGE;
        if (parts.parts() == 1 && firstType != Imf::SCANLINEIMAGE && firstType != Imf::TILEDIMAGE)
            return invalidInput(path + ": a deep image (" + firstType +
                                "); flarekit flares flat images: flatten it first (e.g. oiiotool " +
                                "IN --flatten -o flat.exr)");
        if (parts.parts() == 1 &&
            (part.empty() || part == partName(parts.header(0), 0) || partIndexOf(part) == 0)) {
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
        if (!read && read.error().message == kUnsupportedLayout)
            return unsupportedPart(path, parts.header(chosen), chosen);
        if (!read || parts.parts() == 1) return read;
        if (Status s = checkCopiedParts(path, parts, chosen); !s) return s.error();
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

}  // namespace flarekit::codec
