// SPDX-License-Identifier: Apache-2.0
// zlib's one-shot calls answered by libdeflate and, at level 1, ISA-L
// (src/core/codecs/ZlibOnLibdeflate.cpp): the
// streams are zlib's own format both ways (checked against zlib's stream API, which is not
// replaced), the return codes are zlib's, and OpenEXR's ZIP chunks really go through them.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <random>
#include <vector>

#include "TempDir.h"
#include "core/codecs/ZlibOnLibdeflate.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;

namespace {

//! Bytes a deflater can do something with: runs, a ramp and noise.
std::vector<Bytef> sampleBytes(std::size_t n) {
    std::mt19937 rng(7);
    std::vector<Bytef> bytes(n);
    for (std::size_t i = 0; i < n; ++i)
        bytes[i] = (i / 4096) % 3 == 0   ? Bytef(i / 512)
                   : (i / 4096) % 3 == 1 ? Bytef(i)
                                         : Bytef(rng());
    return bytes;
}

//! `in` through one of zlib's stream coders (deflate or inflate, Z_FINISH in one call), which
//! this process does not replace; `room` bytes of output at most.
template <typename Step, typename End>
std::vector<Bytef> throughZlibStream(z_stream& z, const std::vector<Bytef>& in, std::size_t room,
                                     Step step, End end) {
    std::vector<Bytef> out(room);
    z.next_in = const_cast<Bytef*>(in.data());
    z.avail_in = uInt(in.size());
    z.next_out = out.data();
    z.avail_out = uInt(out.size());
    EXPECT_EQ(step(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    end(&z);
    return out;
}

std::vector<Bytef> inflateWithZlib(const std::vector<Bytef>& in, std::size_t size) {
    z_stream z{};
    EXPECT_EQ(inflateInit(&z), Z_OK);
    return throughZlibStream(z, in, size + 16, inflate, inflateEnd);
}

std::vector<Bytef> deflateWithZlib(const std::vector<Bytef>& in, int level) {
    z_stream z{};
    EXPECT_EQ(deflateInit(&z, level), Z_OK);
    return throughZlibStream(z, in, in.size() + in.size() / 100 + 64, deflate, deflateEnd);
}

}  // namespace

TEST(ZlibOnLibdeflate, TheProcessSymbolsAreOurs) {
    // The loader's global lookup, as libOpenEXR's references see it, finds this program's
    // definitions, not libz's.
    void* zlibs = dlopen("libz.so.1", RTLD_NOW | RTLD_NOLOAD);
    ASSERT_NE(zlibs, nullptr);
    EXPECT_NE(dlsym(RTLD_DEFAULT, "compress2"), dlsym(zlibs, "compress2"));
    EXPECT_NE(dlsym(RTLD_DEFAULT, "uncompress"), dlsym(zlibs, "uncompress"));
    dlclose(zlibs);
}

TEST(ZlibOnLibdeflate, StreamsAreZlibsFormatBothWays) {
    const std::vector<Bytef> original = sampleBytes(300000);
    for (int level : {Z_DEFAULT_COMPRESSION, 0, 1, 4, 6, 9}) {
        // compress2 -> zlib's inflate.
        std::vector<Bytef> packed(compressBound(original.size()));
        uLongf packedSize = packed.size();
        ASSERT_EQ(compress2(packed.data(), &packedSize, original.data(), original.size(), level),
                  Z_OK);
        packed.resize(packedSize);
        EXPECT_EQ(inflateWithZlib(packed, original.size()), original) << "level " << level;
        if (level == 9) {
            EXPECT_LT(packedSize, original.size() / 2);
        }
        // zlib's deflate -> uncompress, with room to spare: the size comes back.
        const std::vector<Bytef> zlibPacked = deflateWithZlib(original, level);
        std::vector<Bytef> back(original.size() + 100);
        uLongf backSize = back.size();
        ASSERT_EQ(uncompress(back.data(), &backSize, zlibPacked.data(), zlibPacked.size()), Z_OK);
        back.resize(backSize);
        EXPECT_EQ(back, original) << "level " << level;
    }
    // compress (no level) is compress2 at the default.
    std::vector<Bytef> packed(compressBound(original.size()));
    uLongf packedSize = packed.size();
    ASSERT_EQ(compress(packed.data(), &packedSize, original.data(), original.size()), Z_OK);
    packed.resize(packedSize);
    EXPECT_EQ(inflateWithZlib(packed, original.size()), original);
}

TEST(ZlibOnLibdeflate, ErrorsAreZlibsCodes) {
    const std::vector<Bytef> original = sampleBytes(50000);
    std::vector<Bytef> packed(compressBound(original.size()));
    uLongf size = 100;  // far too little room
    EXPECT_EQ(compress2(packed.data(), &size, original.data(), original.size(), 6), Z_BUF_ERROR);
    size = packed.size();
    EXPECT_EQ(compress2(packed.data(), &size, original.data(), original.size(), 10),
              Z_STREAM_ERROR);
    EXPECT_EQ(compress2(packed.data(), &size, original.data(), original.size(), -2),
              Z_STREAM_ERROR);
    ASSERT_EQ(compress2(packed.data(), &size, original.data(), original.size(), 6), Z_OK);
    packed.resize(size);
    std::vector<Bytef> back(original.size());
    uLongf room = original.size() - 1;  // one byte short
    EXPECT_EQ(uncompress(back.data(), &room, packed.data(), packed.size()), Z_BUF_ERROR);
    std::vector<Bytef> corrupt = packed;
    corrupt[corrupt.size() / 2] ^= 0x5a;
    corrupt.back() ^= 0xff;  // the Adler-32 too, so a lucky decode is still caught
    room = back.size();
    EXPECT_EQ(uncompress(back.data(), &room, corrupt.data(), corrupt.size()), Z_DATA_ERROR);
    room = back.size();
    EXPECT_EQ(uncompress(back.data(), &room, packed.data(), packed.size() / 2), Z_DATA_ERROR);
}

// Level 1 is ISA-L's deflate: counted as such and zlib's format (zlib's inflate reads it back),
// random bytes included, in the room OpenEXR gives a chunk (the input plus 1% and 100 bytes:
// stored blocks); with far too little room it is zlib's Z_BUF_ERROR.
TEST(ZlibOnLibdeflate, LevelOneIsIsalsDeflateWithLibdeflateBehindIt) {
    const std::vector<Bytef> original = sampleBytes(300000);
    std::vector<Bytef> packed(compressBound(original.size()));
    uLongf size = packed.size();
    const codec::ZlibCalls before = codec::zlibCallsAnsweredByLibdeflate();
    ASSERT_EQ(compress2(packed.data(), &size, original.data(), original.size(), 1), Z_OK);
    const codec::ZlibCalls after = codec::zlibCallsAnsweredByLibdeflate();
    EXPECT_EQ(after.compressedByIsal - before.compressedByIsal, 1u);
    EXPECT_EQ(after.compressed - before.compressed, 1u);
    packed.resize(size);
    EXPECT_EQ(inflateWithZlib(packed, original.size()), original);
    EXPECT_LT(size, original.size() * 3 / 4);  // it does compress

    std::mt19937 rng(11);
    std::vector<Bytef> noise(200000);
    for (Bytef& b : noise) b = Bytef(rng());
    std::vector<Bytef> room(noise.size() + noise.size() / 100 + 100);
    size = room.size();
    const codec::ZlibCalls beforeNoise = codec::zlibCallsAnsweredByLibdeflate();
    ASSERT_EQ(compress2(room.data(), &size, noise.data(), noise.size(), 1), Z_OK);
    EXPECT_EQ(codec::zlibCallsAnsweredByLibdeflate().compressedByIsal,
              beforeNoise.compressedByIsal + 1);
    room.resize(size);
    EXPECT_EQ(inflateWithZlib(room, noise.size()), noise);

    size = 100;
    EXPECT_EQ(compress2(packed.data(), &size, original.data(), original.size(), 1), Z_BUF_ERROR);
}

TEST(ZlibOnLibdeflate, OpenExrZipChunksGoThroughIt) {
    flarekit::test::TempDir dir;
    // 40 lines: 3 chunks of 16 (ZIP), 40 of 1 (ZIPS). Smooth enough that every chunk packs
    // (OpenEXR stores a chunk that does not shrink as it is, without inflating it on read).
    Image image(64, 40);
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i)
        image.data()[i] = float(std::round(std::sin(double(i / 16) * 0.05) * 8.0)) * 0.5f;
    struct Case {
        const char* compression;
        unsigned long chunks;
    };
    for (const Case& c : {Case{"zip", 3}, Case{"zips", 40}}) {
        const std::string path = dir.file(std::string(c.compression) + ".exr");
        WriteOptions options{SampleFormat::Float, true, true, nullptr, {}, {}};
        options.encode.exrCompression = c.compression;
        const codec::ZlibCalls before = codec::zlibCallsAnsweredByLibdeflate();
        ASSERT_TRUE(writeImage(path, image, options).ok());
        const codec::ZlibCalls written = codec::zlibCallsAnsweredByLibdeflate();
        EXPECT_EQ(written.compressed - before.compressed, c.chunks) << c.compression;
        // At the default level, 1, every chunk is ISA-L's.
        EXPECT_EQ(written.compressedByIsal - before.compressedByIsal, c.chunks) << c.compression;
        auto back = readImage(path);
        ASSERT_TRUE(back.ok());
        EXPECT_EQ(codec::zlibCallsAnsweredByLibdeflate().expanded - written.expanded, c.chunks);
        ASSERT_EQ(back.value().image.pixelCount(), image.pixelCount());
        for (std::size_t i = 0; i < image.pixelCount() * 4; ++i)
            ASSERT_EQ(back.value().image.data()[i], image.data()[i]) << c.compression << " " << i;
    }
}

TEST(ZlibOnLibdeflate, TheBenchmarksSwitchHandsCallsBackToZlib) {
    const std::vector<Bytef> original = sampleBytes(100000);
    std::vector<Bytef> ours(compressBound(original.size())), zlibs(ours.size());
    uLongf ourSize = ours.size(), zlibSize = zlibs.size();
    ASSERT_EQ(compress2(ours.data(), &ourSize, original.data(), original.size(), 4), Z_OK);
    const codec::ZlibCalls before = codec::zlibCallsAnsweredByLibdeflate();
    codec::answerZlibCallsWithZlib(true);
    EXPECT_EQ(compress2(zlibs.data(), &zlibSize, original.data(), original.size(), 4), Z_OK);
    codec::answerZlibCallsWithZlib(false);
    EXPECT_EQ(codec::zlibCallsAnsweredByLibdeflate().compressed, before.compressed);
    // Two encoders, two different streams of the same bytes.
    zlibs.resize(zlibSize);
    ours.resize(ourSize);
    EXPECT_NE(zlibs, ours);
    EXPECT_EQ(inflateWithZlib(zlibs, original.size()), original);
    EXPECT_EQ(inflateWithZlib(ours, original.size()), original);
}
