// SPDX-License-Identifier: Apache-2.0
// Image file costs, the fixed part of every whole-process job: the sRGB encode (against the
// binary search it replaced), and reading and writing PNG (per zlib level), EXR and JPEG
// through flarekit's own codecs, on 1 and 2 threads. Files go to /dev/shm where it exists, so
// the figures are the codec's, not the disk's. The image is photographic when Blender's
// studio-light HDRIs are installed (Debian's blender-data: four of them tiled), else the
// repository's synthetic sunset (which compresses far better than a photograph).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "core/Parallel.h"
#include "core/codecs/ZlibOnLibdeflate.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFx.h"

using namespace flarekit;

namespace {

const char* kStudioLights = "/usr/share/blender/datafiles/studiolights/world/";

//! 2048 x 1024: four 1024 x 512 HDRIs tiled, scaled so the sun-free parts sit in [0, 1].
const Image& photo() {
    static const Image image = [] {
        Image out(2048, 1024);
        const char* names[] = {"courtyard", "forest", "city", "interior"};
        for (int t = 0; t < 4; ++t) {
            auto tile = readImage(std::string(kStudioLights) + names[t] + ".exr");
            if (!tile) {
                auto sample = readImage(std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr");
                return sample ? resizeBilinear(sample->image, 2048, 1024) : out;
            }
            const Image& src = tile->image;
            for (int y = 0; y < 512 && y < src.height(); ++y)
                for (int x = 0; x < 1024 && x < src.width(); ++x)
                    out.at((t % 2) * 1024 + x, (t / 2) * 512 + y) = src.at(x, y);
        }
        return out;
    }();
    return image;
}

std::string scratch(const char* name) {
    const std::string dir = std::filesystem::exists("/dev/shm") ? "/dev/shm" : "/tmp";
    return dir + "/flarekit-bench-" + std::to_string(::getpid()) + "-" + name;
}

void setRates(benchmark::State& state, const Image& image) {
    state.SetBytesProcessed(std::int64_t(state.iterations()) *
                            std::int64_t(image.pixelCount() * 16));  // the float RGBA input
    state.counters["MP/s"] = benchmark::Counter(double(image.pixelCount()) * 1e-6,
                                                benchmark::Counter::kIsIterationInvariantRate);
}

//! The encoder before the table: a binary search over the 255 code boundaries.
std::uint8_t binarySearchSrgb8(float linear) {
    static const std::array<float, 255> bounds = [] {
        std::array<float, 255> b{};
        for (int k = 0; k < 255; ++k) {
            const double e = (k + 0.5) / 255.0;
            b[std::size_t(k)] =
                float(e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4));
        }
        return b;
    }();
    if (!(linear > 0.f)) return 0;
    if (linear >= 1.f) return 255;
    return std::uint8_t(std::upper_bound(bounds.begin(), bounds.end(), linear) - bounds.begin());
}

// range(0): threads. RGB codes from float RGBA in 32K-pixel chunks, as writeImage does.
template <typename Code, void (*Encode)(const float*, std::size_t, int, Code*)>
void BM_Encode(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    const Image& image = photo();
    std::vector<Code> codes(image.pixelCount() * 3);
    const int chunks = int((image.pixelCount() + 32767) / 32768);
    for (auto _ : state) {
        parallelFor(0, chunks, 1, [&](int c0, int c1) {
            const std::size_t p0 = std::size_t(c0) * 32768,
                              p1 = std::min(image.pixelCount(), std::size_t(c1) * 32768);
            Encode(image.data() + p0 * 4, p1 - p0, 3, codes.data() + p0 * 3);
        });
        benchmark::DoNotOptimize(codes.data());
    }
    setRates(state, image);
}
void BM_EncodeSrgb8(benchmark::State& state) {
    BM_Encode<std::uint8_t, encodeSrgb8>(state);
}
void BM_EncodeSrgb16(benchmark::State& state) {
    BM_Encode<std::uint16_t, encodeSrgb16>(state);
}

void BM_EncodeSrgb8BinarySearch(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    const Image& image = photo();
    std::vector<std::uint8_t> codes(image.pixelCount() * 3);
    for (auto _ : state) {
        parallelFor(0, image.height(), 16, [&](int y0, int y1) {
            for (std::size_t p = std::size_t(y0) * std::size_t(image.width());
                 p < std::size_t(y1) * std::size_t(image.width()); ++p) {
                for (std::size_t c = 0; c < 3; ++c)
                    codes[p * 3 + c] = binarySearchSrgb8(image.data()[p * 4 + c]);
            }
        });
        benchmark::DoNotOptimize(codes.data());
    }
    setRates(state, image);
}

// range(0): threads. 8-bit RGB codes to float RGBA through the decode table, as readImage does.
void BM_DecodeSrgb8(benchmark::State& state) {
    ThreadLimit limit(int(state.range(0)));
    const Image& image = photo();
    std::vector<std::uint8_t> codes(image.pixelCount() * 3);
    encodeSrgb8(image.data(), image.pixelCount(), 3, codes.data());
    Image out(image.width(), image.height());
    const float* table = srgb8DecodeTable();
    for (auto _ : state) {
        parallelFor(0, image.height(), 16, [&](int y0, int y1) {
            for (std::size_t p = std::size_t(y0) * std::size_t(image.width());
                 p < std::size_t(y1) * std::size_t(image.width()); ++p) {
                float* d = out.data() + p * 4;
                d[0] = table[codes[p * 3]];
                d[1] = table[codes[p * 3 + 1]];
                d[2] = table[codes[p * 3 + 2]];
                d[3] = 1.f;
            }
        });
        benchmark::DoNotOptimize(out.data());
    }
    setRates(state, image);  // bytes: the float RGBA written
}

//! range(0): threads; the file is written once per iteration (encode, temp file, rename).
void writeBench(benchmark::State& state, const char* name, const EncodeSettings& encode = {}) {
    ThreadLimit limit(int(state.range(0)));
    const Image& image = photo();
    const std::string path = scratch(name);
    WriteOptions options;
    options.encode = encode;
    for (auto _ : state) {
        if (Status s = writeImage(path, image, options); !s)
            state.SkipWithError(s.error().message.c_str());
    }
    state.counters["file_MB"] = double(std::filesystem::file_size(path)) * 1e-6;
    std::filesystem::remove(path);
    setRates(state, image);
}

void readBench(benchmark::State& state, const char* name, const EncodeSettings& encode = {}) {
    ThreadLimit limit(int(state.range(0)));
    const Image& image = photo();
    const std::string path = scratch(name);
    WriteOptions options;
    options.encode = encode;
    if (Status s = writeImage(path, image, options); !s)
        state.SkipWithError(s.error().message.c_str());
    for (auto _ : state) {
        auto r = readImage(path);
        if (!r) state.SkipWithError(r.error().message.c_str());
        benchmark::DoNotOptimize(r);
    }
    std::filesystem::remove(path);
    setRates(state, image);
}

void BM_WritePng(benchmark::State& state) {
    EncodeSettings encode;
    encode.pngCompression = int(state.range(1));
    writeBench(state, "w.png", encode);
}
void BM_ReadPng(benchmark::State& state) {
    readBench(state, "r.png");
}
void BM_WriteExrHalf(benchmark::State& state) {
    writeBench(state, "w.exr");
}
void BM_ReadExrHalf(benchmark::State& state) {
    readBench(state, "r.exr");
}
// range(1): 1 for zlib itself, 0 for libdeflate answering OpenEXR's zlib calls (what the CLI
// does, src/core/codecs/ZlibOnLibdeflate.cpp). OpenEXR's ZIP at its default level, 4.
void zipBench(benchmark::State& state, bool write) {
    codec::answerZlibCallsWithZlib(state.range(1) == 1);
    EncodeSettings zip;
    zip.exrCompression = "zip";
    if (write) {
        writeBench(state, "wz.exr", zip);
    } else {
        readBench(state, "rz.exr", zip);
    }
    codec::answerZlibCallsWithZlib(false);
}
void BM_WriteExrZip(benchmark::State& state) {
    zipBench(state, true);
}
void BM_ReadExrZip(benchmark::State& state) {
    zipBench(state, false);
}
// range(1): the zlib level of ZIP chunks, as --exr-zip-level: 1 is ISA-L's deflate (the
// default), 2 and up libdeflate's; file_MB says what each level gives for its time.
void BM_WriteExrZipLevel(benchmark::State& state) {
    EncodeSettings zip;
    zip.exrCompression = "zip";
    zip.exrZipLevel = int(state.range(1));
    writeBench(state, "wl.exr", zip);
}
void BM_WriteJpeg(benchmark::State& state) {
    writeBench(state, "w.jpg");
}
void BM_ReadJpeg(benchmark::State& state) {
    readBench(state, "r.jpg");
}

}  // namespace

BENCHMARK(BM_EncodeSrgb8)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();
BENCHMARK(BM_EncodeSrgb8BinarySearch)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();
BENCHMARK(BM_DecodeSrgb8)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();
BENCHMARK(BM_EncodeSrgb16)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();
BENCHMARK(BM_WritePng)
    ->ArgsProduct({{1, 2}, {0, 1, 6}})
    ->ArgNames({"threads", "level"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPng)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteExrHalf)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadExrHalf)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteExrZip)
    ->ArgsProduct({{1, 2}, {1, 0}})
    ->ArgNames({"threads", "zlib"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteExrZipLevel)
    ->ArgsProduct({{1, 2}, {1, 2, 4}})
    ->ArgNames({"threads", "level"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadExrZip)
    ->ArgsProduct({{1, 2}, {1, 0}})
    ->ArgNames({"threads", "zlib"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteJpeg)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadJpeg)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
