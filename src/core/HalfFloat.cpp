// SPDX-License-Identifier: Apache-2.0
#include "core/HalfFloat.h"

#include <Imath/half.h>

#include <cmath>

#if defined(__x86_64__)
#include <cpuid.h>
#include <immintrin.h>
#endif

namespace flarekit {

namespace {

float halfBitsToFloat(std::uint16_t bits) {
    half h;
    h.setBits(bits);
    return float(h);
}

void floatsToHalfPortable(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out) {
    for (std::size_t p = 0; p < pixels; ++p, rgba += 4, out += channels) {
        for (int c = 0; c < channels; ++c) {
            const float v = rgba[c];
            out[c] = half(sanitisedSample(v)).bits();
        }
    }
}

#if defined(__x86_64__)
//! One F16C conversion per pixel (its four channels), as sanitisedSample: NaN masked to 0,
//! then everything clamped to +-65504.
__attribute__((target("avx,f16c"))) inline __m128i pixelToHalves(const float* rgba) {
    const __m128 v = _mm_loadu_ps(rgba);
    const __m128 finite = _mm_andnot_ps(_mm_cmpunord_ps(v, v), v);
    const __m128 clamped =
        _mm_min_ps(_mm_max_ps(finite, _mm_set1_ps(-kLargestHalf)), _mm_set1_ps(kLargestHalf));
    return _mm_cvtps_ph(clamped, _MM_FROUND_TO_NEAREST_INT);
}

//! The four halves are stored as one 8-byte word. With three channels the word's last half
//! spills into the next pixel's first, which that pixel then overwrites; the last pixel is
//! copied half by half so nothing is written past `out`'s end.
__attribute__((target("avx,f16c"))) void floatsToHalfF16c(const float* rgba, std::size_t pixels,
                                                          int channels, std::uint16_t* out) {
    std::size_t p = 0;
    if (channels == 4 || channels == 3) {
        for (; p + 1 < pixels; ++p, rgba += 4, out += channels)
            _mm_storel_epi64(reinterpret_cast<__m128i*>(out), pixelToHalves(rgba));
    }
    for (; p < pixels; ++p, rgba += 4, out += channels) {
        alignas(16) std::uint16_t four[8];
        _mm_store_si128(reinterpret_cast<__m128i*>(four), pixelToHalves(rgba));
        for (int c = 0; c < channels; ++c) out[c] = four[c];
    }
}

__attribute__((target("avx,f16c"))) void halfsToFloatsF16c(const std::uint16_t* in,
                                                           std::size_t count, float* out) {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m128i h = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + i));
        _mm256_storeu_ps(out + i, _mm256_cvtph_ps(h));
    }
    for (; i < count; ++i) out[i] = halfBitsToFloat(in[i]);
}

//! F16C and AVX from CPUID leaf 1 (ECX bits 29 and 28), with the OS saving the AVX registers
//! (OSXSAVE, bit 27, and XCR0's SSE and AVX state bits): what GCC's __builtin_cpu_supports
//! reads, spelt out because clang 14 does not know "f16c" there.
__attribute__((target("xsave"))) bool detectF16c() {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
    const bool f16c = ecx & (1u << 29), avx = ecx & (1u << 28), osxsave = ecx & (1u << 27);
    return f16c && avx && osxsave && (_xgetbv(0) & 6) == 6;
}

bool hasF16c() {
    static const bool yes = detectF16c();
    return yes;
}
#endif

}  // namespace

void floatsToHalf(const float* rgba, std::size_t pixels, int channels, std::uint16_t* out) {
#if defined(__x86_64__)
    if (hasF16c()) return floatsToHalfF16c(rgba, pixels, channels, out);
#endif
    floatsToHalfPortable(rgba, pixels, channels, out);
}

void halfsToFloats(const std::uint16_t* in, std::size_t count, float* out) {
#if defined(__x86_64__)
    if (hasF16c()) return halfsToFloatsF16c(in, count, out);
#endif
    for (std::size_t i = 0; i < count; ++i) out[i] = halfBitsToFloat(in[i]);
}

}  // namespace flarekit
