// SPDX-License-Identifier: Apache-2.0
// Saturating add with SIMD: 32 bytes per instruction with AVX2 (vpaddusb), 16 with SSE2
// (paddusb), picked once at run time; the hardware saturating add is exactly Figure 7's
// min(s + d, 255). Tails shorter than a vector use the scalar formula.
// Large spans (whole frames) are bound by memory traffic, not arithmetic: there the output is
// written with streaming (non-temporal) stores, which skip reading the destination lines into
// cache first, the same choice glibc's memcpy makes for large copies. AVX-512BW was tried and
// measured no faster than AVX2 on this workload (docs/benchmarks.md), so it is not used.
#include <cstdint>

#include "flarekit/Blend.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define FLAREKIT_X86 1
#endif

namespace flarekit::blend8 {

namespace {

void addTail(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out[i] = add(a[i], b[i]);
}

#ifdef FLAREKIT_X86
void addSse2(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n) {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const __m128i va = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + i));
        const __m128i vb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + i));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_adds_epu8(va, vb));
    }
    addTail(a + i, b + i, out + i, n - i);
}

//! Spans at least this long use streaming stores: 4 MiB is past the per-core L2 of current
//! x86 parts, so the output would leave the cache before anyone re-read it anyway.
constexpr std::size_t kStreamingBytes = std::size_t(4) << 20;

//! Adds 64 bytes per iteration (two vectors keep both load ports busy) from i while a whole
//! block fits; Stream picks streaming stores (out + i must then be 32-byte aligned).
template <bool Stream>
__attribute__((target("avx2"))) std::size_t addAvx2Blocks(const std::uint8_t* a,
                                                          const std::uint8_t* b, std::uint8_t* out,
                                                          std::size_t i, std::size_t n) {
    for (; i + 64 <= n; i += 64) {
        for (std::size_t k = i; k < i + 64; k += 32) {
            const __m256i va = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + k));
            const __m256i vb = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + k));
            if constexpr (Stream) {
                _mm256_stream_si256(reinterpret_cast<__m256i*>(out + k), _mm256_adds_epu8(va, vb));
            } else {
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + k), _mm256_adds_epu8(va, vb));
            }
        }
    }
    return i;
}

__attribute__((target("avx2"))) void addAvx2(const std::uint8_t* a, const std::uint8_t* b,
                                             std::uint8_t* out, std::size_t n) {
    std::size_t i = 0;
    if (n >= kStreamingBytes) {
        // Streaming stores need 32-byte aligned destinations: the head goes through the formula.
        i = (32 - (reinterpret_cast<std::uintptr_t>(out) & 31)) & 31;
        addTail(a, b, out, i);
        i = addAvx2Blocks<true>(a, b, out, i, n);
        _mm_sfence();  // order the streaming stores before any later read of `out`
    }
    i = addAvx2Blocks<false>(a, b, out, i, n);
    addSse2(a + i, b + i, out + i, n - i);  // the last 0..63 bytes
}
#endif

using AddFn = void (*)(const std::uint8_t*, const std::uint8_t*, std::uint8_t*, std::size_t);

struct Dispatch {
    AddFn fn;
    std::string_view isa;
};

Dispatch pick() {
#ifdef FLAREKIT_X86
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2")) return {addAvx2, "avx2"};
    return {addSse2, "sse2"};
#else
    return {addTail, "scalar"};
#endif
}

const Dispatch& dispatch() {
    static const Dispatch d = pick();
    return d;
}

}  // namespace

void addSpanSimd(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n) {
    dispatch().fn(a, b, out, n);
}

std::string_view addSimdIsa() {
    return dispatch().isa;
}

}  // namespace flarekit::blend8
