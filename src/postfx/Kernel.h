// SPDX-License-Identifier: Apache-2.0
// What every CPU post-process kernel shares with its GLSL twin (shaders/postfx_common.glsl):
// a 4-wide float vector per RGBA pixel (one SSE register: the SIMD of the CPU chain), texel
// fetches clamped to the edge, and bilinear filtering written out by hand. Hardware filtering
// would round its weights to 8 bits on most GPUs; doing it the same way on both sides is what
// lets the CPU and GL chains agree to 1e-3.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/Parallel.h"
#include "flarekit/Image.h"

namespace flarekit::postfx {

typedef float F4 __attribute__((vector_size(16)));  // NOLINT: GCC/Clang vector extension

inline F4 splat(float s) {
    return F4{s, s, s, s};
}
inline F4 rgbOnly(F4 v) {
    return F4{v[0], v[1], v[2], 0.f};
}
inline F4 max0(F4 v) {
    return v > splat(0.f) ? v : splat(0.f);
}  // lane-wise select
inline F4 maxv(F4 a, F4 b) {
    return a > b ? a : b;
}

struct Vec2 {
    float x = 0, y = 0;
};

//! A read-only view of an Image for kernels.
struct Tex {
    const float* data = nullptr;
    int width = 0, height = 0;
    Tex() = default;
    explicit Tex(const Image& image)
        : data(image.data()), width(image.width()), height(image.height()) {}

    F4 texel(int x, int y) const {  // GLSL texelFetch: no bounds check
        F4 v;
        std::memcpy(&v, data + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4,
                    sizeof v);
        return v;
    }
};

//! postfx_common.glsl fetchClamped: the texel nearest to (x, y) inside the image.
inline F4 fetchClamped(const Tex& t, int x, int y) {
    return t.texel(std::clamp(x, 0, t.width - 1), std::clamp(y, 0, t.height - 1));
}

//! GLSL floor() for the coordinates kernels use (|s| < 2^31): a truncation and a compare, where
//! std::floor is a libm call on baseline x86-64 (no SSE4.1 round instruction).
inline int floorToInt(float s) {
    const int i = int(s);
    return i - (float(i) > s ? 1 : 0);
}

//! postfx_common.glsl pointSample: the seed's PointSampler at normalised (u, v), clamped.
inline F4 pointSample(const Tex& t, Vec2 uv) {
    return fetchClamped(t, floorToInt(uv.x * float(t.width)), floorToInt(uv.y * float(t.height)));
}

//! postfx_common.glsl fetchLight: fetchClamped as light, which is never negative: NaN, Inf and
//! negative values read as 0, so one bad input pixel cannot spread over the whole flare, and
//! a resize's ringing (a Lanczos filter leaves -3,600 beside a sun of 50,000) does not cancel
//! the light beside it.
inline F4 fetchLight(const Tex& t, int x, int y) {
    const F4 v = fetchClamped(t, x, y);
    // Lane-wise: a float is NaN or infinite exactly when its exponent bits are all ones.
    typedef int I4 __attribute__((vector_size(16)));  // NOLINT: GCC/Clang vector extension
    const I4 exponent = I4(v) & 0x7F800000;
    const F4 finite = exponent != 0x7F800000 ? v : splat(0.f);
    return finite > splat(0.f) ? finite : splat(0.f);
}

//! postfx_common.glsl bilinear: linear filtering at normalised (u, v), clamp-to-edge.
template <F4 (*Fetch)(const Tex&, int, int) = fetchClamped>
inline F4 bilinear(const Tex& t, Vec2 uv) {
    const float sx = uv.x * float(t.width) - 0.5f, sy = uv.y * float(t.height) - 0.5f;
    const int x = floorToInt(sx), y = floorToInt(sy);
    const float fx = sx - float(x), fy = sy - float(y);
    const F4 a = Fetch(t, x, y), b = Fetch(t, x + 1, y);
    const F4 c = Fetch(t, x, y + 1), d = Fetch(t, x + 1, y + 1);
    const F4 top = a + (b - a) * fx, bottom = c + (d - c) * fx;
    return top + (bottom - top) * fy;
}
//! postfx_common.glsl bilinearLight.
inline F4 bilinearLight(const Tex& t, Vec2 uv) {
    return bilinear<fetchLight>(t, uv);
}

//! The centre of output pixel (x, y) in normalised coordinates, as gl_FragCoord.xy * invSize.
inline Vec2 pixelUv(int x, int y, Vec2 invSize) {
    return {(float(x) + 0.5f) * invSize.x, (float(y) + 0.5f) * invSize.y};
}
inline Vec2 inverseSize(int width, int height) {
    return {1.f / float(width), 1.f / float(height)};
}

//! bilinear(t, pixelUv(x, y, invOutSize)) for whole output rows, evaluated separably. Each
//! output column's clamped pair of source texels and weight are found once per pass
//! (BilinearColumns); a source row is filtered across once and kept while the output rows
//! between it and the next read it (BilinearRows). Every value is bilinear()'s own expression in
//! its own order (top = a + (b - a) fx, bottom alike, then top + (bottom - top) fy), so the
//! results are bilinear()'s bit for bit (tested); an upsample by 4 filters a quarter as many
//! rows across as it writes.
struct BilinearColumns {
    struct Column {
        int left = 0, right = 0;  //!< clamped source columns of bilinear()'s a and b
        float fx = 0.f;
    };
    Tex source;
    Vec2 invOutSize;
    std::vector<Column> columns;

    BilinearColumns(const Tex& t, int outWidth, Vec2 invOut) : source(t), invOutSize(invOut) {
        columns.resize(std::size_t(std::max(0, outWidth)));
        for (int x = 0; x < outWidth; ++x) {
            const float sx = pixelUv(x, 0, invOut).x * float(t.width) - 0.5f;
            const int left = floorToInt(sx);
            columns[std::size_t(x)] = {std::clamp(left, 0, t.width - 1),
                                       std::clamp(left + 1, 0, t.width - 1), sx - float(left)};
        }
    }
};

//! One task's walk down the output rows (increasing y): the two filtered source rows in use.
class BilinearRows {
  public:
    explicit BilinearRows(const BilinearColumns& c) : m_c(c) {
        for (auto& row : m_rows) row.resize(c.columns.size());
    }
    struct Pair {
        const F4* top;
        const F4* bottom;
        float fy;
    };
    //! The filtered source rows above and below output row y and the weight between them.
    Pair at(int y) {
        const Tex& t = m_c.source;
        const float sy = pixelUv(0, y, m_c.invOutSize).y * float(t.height) - 0.5f;
        const int above = floorToInt(sy);
        const int top = std::clamp(above, 0, t.height - 1),
                  bottom = std::clamp(above + 1, 0, t.height - 1);
        const F4* upper = filtered(top, bottom);
        return {upper, filtered(bottom, top), sy - float(above)};
    }

  private:
    //! Source row `row` filtered across, in a slot that does not hold `keep`.
    const F4* filtered(int row, int keep) {
        for (std::size_t i = 0; i < 2; ++i)
            if (m_keys[i] == row) return m_rows[i].data();
        const std::size_t slot = m_keys[0] == keep ? 1 : 0;
        m_keys[slot] = row;
        F4* out = m_rows[slot].data();
        const Tex& t = m_c.source;
        for (std::size_t x = 0; x < m_c.columns.size(); ++x) {
            const BilinearColumns::Column& c = m_c.columns[x];
            const F4 a = t.texel(c.left, row), b = t.texel(c.right, row);
            out[x] = a + (b - a) * c.fx;
        }
        return out;
    }

    const BilinearColumns& m_c;
    std::array<std::vector<F4>, 2> m_rows;
    std::array<int, 2> m_keys{-1, -1};
};

//! F4 stored at a float address of any alignment. A typed store, unlike memcpy's byte-typed one,
//! tells the compiler it cannot change the kernel's pointers and sizes, so they stay in
//! registers across the row instead of being read again for every pixel.
typedef float F4Unaligned __attribute__((vector_size(16), aligned(4)));  // NOLINT: GCC/Clang

//! Rows per parallel task for an output `width` pixels wide: about 16,384 pixels (256 KiB of
//! output), enough work to outweigh a task's start.
inline int rowGrain(int width) {
    return std::max(1, 16384 / std::max(1, width));
}

//! Runs kernel(x, y) -> F4 for every pixel of `out`, rows in parallel: the CPU's draw call.
template <typename Kernel>
void runPass(Image& out, const Kernel& kernel) {
    const int width = out.width();
    parallelFor(0, out.height(), rowGrain(width), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* row = out.row(y);
            for (int x = 0; x < width; ++x)
                *reinterpret_cast<F4Unaligned*>(row + std::size_t(x) * 4) = kernel(x, y);
        }
    });
}

//! Runs kernel(x, y, up) -> F4 for every pixel of `out`, rows in parallel, where `up` is
//! bilinear(columns.source, pixelUv(x, y)) filtered separably (BilinearRows: the same value bit
//! for bit), for passes that upsample a smaller buffer to every output pixel.
template <typename Kernel>
void runUpsamplePass(Image& out, const BilinearColumns& columns, const Kernel& kernel) {
    const int width = out.width();
    parallelFor(0, out.height(), rowGrain(width), [&](int y0, int y1) {
        BilinearRows rows(columns);
        for (int y = y0; y < y1; ++y) {
            const BilinearRows::Pair p = rows.at(y);
            float* row = out.row(y);
            for (int x = 0; x < width; ++x) {
                const F4 top = p.top[x], bottom = p.bottom[x];
                *reinterpret_cast<F4Unaligned*>(row + std::size_t(x) * 4) =
                    kernel(x, y, top + (bottom - top) * p.fy);
            }
        }
    });
}

//! 1 / sqrt(2): the distance from the centre to a corner in [-1, 1] coordinates is sqrt(2).
inline constexpr float kInvCornerDistance = 0.70710678f;

//! The modern falloff of a ghost at normalised p (John Chapman, "Pseudo Lens Flare", 2013).
inline float centreFalloff(Vec2 p, float exponent) {
    if (exponent <= 0.f) return 1.f;
    const float r = std::sqrt(p.x * p.x + p.y * p.y) * kInvCornerDistance;
    return std::pow(std::max(0.f, 1.f - r), exponent);
}

//! How much of a tap at s (uv in the buffer it samples) counts: 1 inside, easing to 0 over the
//! last `fade` of the buffer on every side (smoothstep in x times smoothstep in y), so a ghost
//! or halo that mirrors or magnifies the buffer never shows its border as a straight edge.
//! fade 0 is the seed's hard cut: every tap inside [0, 1] counts fully. The caller still skips
//! taps outside [0, 1].
inline float borderWindow(Vec2 s, float fade) {
    if (fade <= 0.f) return 1.f;
    const float tx = std::clamp(std::min(s.x, 1.f - s.x) / fade, 0.f, 1.f);
    const float ty = std::clamp(std::min(s.y, 1.f - s.y) / fade, 0.f, 1.f);
    return tx * tx * (3.f - 2.f * tx) * (ty * ty * (3.f - 2.f * ty));
}

//! Half the size, rounded up, never below 1: each level of the chain.
inline int halfSize(int n) {
    return std::max(1, (n + 1) / 2);
}

}  // namespace flarekit::postfx
