// SPDX-License-Identifier: Apache-2.0
// zlib's one-shot calls, `compress`, `compress2` and `uncompress`, answered by libdeflate
// (Eric Biggers' whole-buffer DEFLATE library) and, at level 1, by Intel's ISA-L (igzip) for
// the program this object is linked into.
//
// Why: OpenEXR 3.1 (Debian 12's) compresses and expands every ZIP and ZIPS chunk through these
// three calls, and zlib made ZIP the largest cost of a whole `postfx` run on an EXR (at 1080p,
// 38% of the process's CPU: level-4 deflate of the output and inflate of the input). libdeflate
// does the same work in about a third of the time, and OpenEXR 3.2 itself moved to it for
// that reason. Even so, libdeflate's level 1 was still a quarter of a `postfx` run's CPU; ISA-L's
// level 1 deflates OpenEXR's chunks 3-5x faster again, for files 4-6% larger on photographs and
// HDRIs (15% on a smooth synthetic sky): docs/formats.md has the figures. So level 1, flarekit's
// default, is ISA-L's level 1; levels 2-9 stay libdeflate's, whose level 2 makes files a little
// smaller than level 1 made before. The files stay standard zlib streams: any reader decodes them.
//
// How: a definition in the executable comes first in the dynamic linker's search, so
// libOpenEXR's unversioned references bind here (the linker exports these symbols because a
// shared library in the link uses them). Only the executables that link this object (the CLI,
// the tests and the benches) get it: the engine library leaves its host's zlib alone. The
// stream API (deflateInit, inflate), which libpng and libtiff use, is not touched.
#include <dlfcn.h>
#include <isa-l/igzip_lib.h>
#include <libdeflate.h>
#include <zlib.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#include "core/codecs/ZlibOnLibdeflate.h"

namespace {

std::atomic<unsigned long> g_compressed{0};
std::atomic<unsigned long> g_compressedByIsal{0};
std::atomic<unsigned long> g_expanded{0};
std::atomic<bool> g_zlibItself{false};

//! zlib's own definition of `name`: the next one after this program's in the lookup order.
template <typename Function>
Function zlibs(const char* name) {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
}

//! One compressor per zlib level (0-9) and one decompressor per thread: libdeflate's objects are
//! not shared between threads, and OpenEXR calls from every thread of its pool.
struct ThreadCoders {
    libdeflate_compressor* compressors[10] = {};
    libdeflate_decompressor* decompressor = nullptr;
    ~ThreadCoders() {
        for (libdeflate_compressor* c : compressors) libdeflate_free_compressor(c);
        libdeflate_free_decompressor(decompressor);
    }
};

ThreadCoders& coders() {
    thread_local ThreadCoders t;
    return t;
}

//! ISA-L's stateless level-1 deflate with a zlib header and Adler-32 trailer, on this thread's
//! stream state (82 KB) and level-1 hash buffer (ISAL_DEF_LVL1_DEFAULT, 276 KiB), made once per
//! thread. Returns the bytes written, or 0 when they did not fit in `room` (bytes that do not
//! compress already go out as stored blocks, so that is when even those do not fit) or ISA-L
//! refused; the caller then asks libdeflate, which answers Z_BUF_ERROR if it cannot fit them
//! either.
std::size_t isalDeflateLevel1(const Bytef* source, std::size_t size, Bytef* dest,
                              std::size_t room) {
    struct State {
        isal_zstream stream;
        std::vector<std::uint8_t> levelBuffer = std::vector<std::uint8_t>(ISAL_DEF_LVL1_DEFAULT);
    };
    // Made on first use, not at thread start: a failed allocation must not throw out of zlib's
    // C interface, so it is caught here and libdeflate gets the call.
    thread_local std::unique_ptr<State> state;
    if (!state) {
        try {
            state = std::make_unique<State>();
        } catch (const std::bad_alloc&) {
            return 0;
        }
    }
    isal_zstream& z = state->stream;
    isal_deflate_stateless_init(&z);
    z.level = 1;
    z.level_buf = state->levelBuffer.data();
    z.level_buf_size = std::uint32_t(state->levelBuffer.size());
    z.gzip_flag = IGZIP_ZLIB;
    z.end_of_stream = 1;
    z.flush = NO_FLUSH;
    z.next_in = const_cast<Bytef*>(source);
    z.avail_in = std::uint32_t(size);
    z.next_out = dest;
    z.avail_out = std::uint32_t(room);
    if (isal_deflate_stateless(&z) != COMP_OK) return 0;
    return z.total_out;
}

}  // namespace

extern "C" {

// zlib: "compress2 returns Z_OK if success, Z_MEM_ERROR if there was not enough memory,
// Z_BUF_ERROR if there was not enough room in the output buffer, Z_STREAM_ERROR if the level
// parameter is invalid." Levels share zlib's scale (1 fastest, 9 smallest); zlib's
// Z_DEFAULT_COMPRESSION (-1) is its level 6, which is libdeflate's default too.
int compress2(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen, int level) {
    if (g_zlibItself.load(std::memory_order_relaxed)) {
        static const auto zlib =
            zlibs<int (*)(Bytef*, uLongf*, const Bytef*, uLong, int)>("compress2");
        return zlib(dest, destLen, source, sourceLen, level);
    }
    if (level == Z_DEFAULT_COMPRESSION) level = 6;
    if (level < 0 || level > 9) return Z_STREAM_ERROR;
    // ISA-L takes 32-bit sizes; a chunk of OpenEXR's is far below that.
    if (level == 1 && sourceLen < (1ul << 31) && *destLen < (1ul << 31)) {
        if (const std::size_t n = isalDeflateLevel1(source, sourceLen, dest, *destLen)) {
            *destLen = uLongf(n);
            g_compressed.fetch_add(1, std::memory_order_relaxed);
            g_compressedByIsal.fetch_add(1, std::memory_order_relaxed);
            return Z_OK;
        }
    }
    libdeflate_compressor*& c = coders().compressors[level];
    if (!c) c = libdeflate_alloc_compressor(level);
    if (!c) return Z_MEM_ERROR;
    const std::size_t n = libdeflate_zlib_compress(c, source, sourceLen, dest, *destLen);
    if (n == 0) return Z_BUF_ERROR;
    *destLen = uLongf(n);
    g_compressed.fetch_add(1, std::memory_order_relaxed);
    return Z_OK;
}

int compress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen) {
    return compress2(dest, destLen, source, sourceLen, Z_DEFAULT_COMPRESSION);
}

// zlib: "uncompress returns Z_OK if success, Z_MEM_ERROR if there was not enough memory,
// Z_BUF_ERROR if there was not enough room in the output buffer, or Z_DATA_ERROR if the input
// data was corrupted or incomplete"; on entry *destLen is the room, on return the size.
int uncompress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen) {
    if (g_zlibItself.load(std::memory_order_relaxed)) {
        static const auto zlib = zlibs<int (*)(Bytef*, uLongf*, const Bytef*, uLong)>("uncompress");
        return zlib(dest, destLen, source, sourceLen);
    }
    libdeflate_decompressor*& d = coders().decompressor;
    if (!d) d = libdeflate_alloc_decompressor();
    if (!d) return Z_MEM_ERROR;
    std::size_t n = 0;
    switch (libdeflate_zlib_decompress(d, source, sourceLen, dest, *destLen, &n)) {
        case LIBDEFLATE_SUCCESS:
            *destLen = uLongf(n);
            g_expanded.fetch_add(1, std::memory_order_relaxed);
            return Z_OK;
        case LIBDEFLATE_INSUFFICIENT_SPACE:
            return Z_BUF_ERROR;
        default:
            return Z_DATA_ERROR;
    }
}

}  // extern "C"

namespace flarekit::codec {

void answerZlibCallsWithZlib(bool zlib) {
    g_zlibItself.store(zlib, std::memory_order_relaxed);
}

ZlibCalls zlibCallsAnsweredByLibdeflate() {
    return {g_compressed.load(std::memory_order_relaxed),
            g_expanded.load(std::memory_order_relaxed),
            g_compressedByIsal.load(std::memory_order_relaxed)};
}

}  // namespace flarekit::codec
