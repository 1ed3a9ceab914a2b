// SPDX-License-Identifier: Apache-2.0
// Seed 002's integer blend formulas, tested exhaustively: every (s, d, a) for the alpha
// modes (256^3), every (s, d) for the three saturating adds, through the span functions.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "flarekit/Blend.h"

using namespace flarekit;

namespace {

// For one alpha value, src pixels run over every s (in R, G and B rotated) and dst over every d.
struct AlphaGrid {
    std::vector<std::uint8_t> src, dst;
    explicit AlphaGrid(int a) : src(65536 * 4), dst(65536 * 3) {
        for (int s = 0; s < 256; ++s) {
            for (int d = 0; d < 256; ++d) {
                const std::size_t i = std::size_t(s * 256 + d);
                src[i * 4 + 0] = std::uint8_t(s);
                src[i * 4 + 1] = std::uint8_t(255 - s);
                src[i * 4 + 2] = std::uint8_t(s ^ 0x5A);
                src[i * 4 + 3] = std::uint8_t(a);
                for (int c = 0; c < 3; ++c) dst[i * 3 + std::size_t(c)] = std::uint8_t(d);
            }
        }
    }
};

template <typename Span, typename Expected>
void checkEveryTriple(Span span, Expected expected) {
    for (int a = 0; a < 256; ++a) {
        AlphaGrid g(a);
        span(g.src.data(), g.dst.data(), g.dst.size() / 3);
        for (std::size_t i = 0; i < 65536; ++i) {
            for (int c = 0; c < 3; ++c) {
                const int s = g.src[i * 4 + std::size_t(c)], d = int(i % 256);
                const int want = expected(s, d, a);
                ASSERT_GE(want, 0);
                ASSERT_LE(want, 255) << "s=" << s << " d=" << d << " a=" << a;
                ASSERT_EQ(g.dst[i * 3 + std::size_t(c)], want)
                    << "s=" << s << " d=" << d << " a=" << a;
            }
        }
    }
}

}  // namespace

TEST(Blend8, AlphaFigure1IsExactOverEveryInput) {
    checkEveryTriple([](auto* s, auto* d, std::size_t n) { blend8::alphaSpan(s, d, 3, n); },
                     [](int s, int d, int a) { return (s * a + d * (255 - a)) / 255; });
}

TEST(Blend8, AlphaShiftFigure3IsExactOverEveryInput) {
    checkEveryTriple([](auto* s, auto* d, std::size_t n) { blend8::alphaShiftSpan(s, d, 3, n); },
                     [](int s, int d, int a) { return (s * a + d * (255 - a)) >> 8; });
}

TEST(Blend8, PremultipliedFigure6IsExactOverEveryInput) {
    checkEveryTriple(
        [](auto* s, auto* d, std::size_t n) {
            std::vector<std::uint8_t> stored(n * 4);
            blend8::toPremultipliedInverse(s, stored.data(), n);
            blend8::premultipliedSpan(stored.data(), d, 3, n);
        },
        [](int s, int d, int a) { return s * a / 255 + ((d * (255 - a)) >> 8); });
}

TEST(Blend8, KnownValuesShowEachFormulasCharacter) {
    EXPECT_EQ(blend8::alpha(255, 255, 128), 255);       // /255 keeps white white
    EXPECT_EQ(blend8::alphaShift(255, 255, 128), 254);  // >>8 loses one level (Figure 3's cost)
    EXPECT_EQ(blend8::alpha(200, 100, 0), 100);
    EXPECT_EQ(blend8::alpha(200, 100, 255), 200);
    EXPECT_EQ(blend8::alphaShift(200, 100, 255), 199);
    EXPECT_EQ(blend8::premultiply(200, 128), 100);  // 25600 / 255 = 100.39
}

TEST(Blend8, Figure6AsPrintedWouldParseDifferently) {
    // "source1_r + (source2_r * alpha) >> 8" in C is (s + d*ia) >> 8; flarekit implements
    // s + ((d*ia) >> 8). The two differ, e.g. for s' = 10, d = 100, ia = 128:
    const int sPre = 10, d = 100, ia = 128;
    EXPECT_EQ((sPre + d * ia) >> 8, 50);
    EXPECT_EQ(blend8::premultiplied(sPre, d, ia), 60);
}

TEST(Blend8, AddThreeWaysAgreeOnEveryPair) {
    std::vector<std::uint8_t> a(65536), b(65536), want(65536);
    for (int s = 0; s < 256; ++s) {
        for (int d = 0; d < 256; ++d) {
            const std::size_t i = std::size_t(s * 256 + d);
            a[i] = std::uint8_t(s);
            b[i] = std::uint8_t(d);
            want[i] = std::uint8_t(std::min(s + d, 255));  // Figure 7
        }
    }
    for (auto fn : {blend8::addSpanScalar16, blend8::addSpanLut, blend8::addSpanSimd}) {
        std::vector<std::uint8_t> out(65536, 0xCD);
        fn(a.data(), b.data(), out.data(), out.size());
        ASSERT_EQ(out, want);
    }
}

TEST(Blend8, SimdAddHandlesEveryAlignmentAndTail) {
    std::vector<std::uint8_t> a(300), b(300);
    for (std::size_t i = 0; i < a.size(); ++i) {
        a[i] = std::uint8_t(i * 37 + 11);
        b[i] = std::uint8_t(i * 91 + 200);
    }
    for (std::size_t offset = 0; offset < 33; ++offset) {
        for (std::size_t n = 0; n + offset <= 200; ++n) {
            std::vector<std::uint8_t> simd(a.size(), 7), scalar(a.size(), 7);
            blend8::addSpanSimd(a.data() + offset, b.data() + offset, simd.data() + offset, n);
            blend8::addSpanScalar16(a.data() + offset, b.data() + offset, scalar.data() + offset,
                                    n);
            ASSERT_EQ(simd, scalar)
                << "offset " << offset << " n " << n;  // also: nothing written past n
        }
    }
    // In place (out aliases a), as `flarekit blend` uses it.
    std::vector<std::uint8_t> inPlace = a, want(a.size());
    blend8::addSpanScalar16(a.data(), b.data(), want.data(), a.size());
    blend8::addSpanSimd(inPlace.data(), b.data(), inPlace.data(), a.size());
    EXPECT_EQ(inPlace, want);
}

TEST(Blend8, SimdAddStreamingPathForWholeFramesMatches) {
    // Spans of 4 MiB and more take the streaming-store path: test it at an odd alignment.
    const std::size_t n = (std::size_t(9) << 20) + 77;
    std::vector<std::uint8_t> a(n + 3), b(n + 3), simd(n + 3, 1), scalar(n + 3, 1);
    for (std::size_t i = 0; i < a.size(); ++i) {
        a[i] = std::uint8_t(i * 2654435761u >> 13);
        b[i] = std::uint8_t(i * 40503u >> 5);
    }
    blend8::addSpanSimd(a.data() + 3, b.data() + 3, simd.data() + 3, n);
    blend8::addSpanScalar16(a.data() + 3, b.data() + 3, scalar.data() + 3, n);
    EXPECT_EQ(simd, scalar);
}

TEST(Blend8, LutIsFigure8) {
    const std::uint8_t* alut = blend8::addLut();
    for (int i = 0; i < 512; ++i) ASSERT_EQ(alut[i], i > 255 ? 255 : i);
}

TEST(Blend8, ImagesRejectMismatchedSizesAndChannels) {
    Image8 src{2, 2, 4, std::vector<std::uint8_t>(16, 100)};
    Image8 dst{2, 3, 3, std::vector<std::uint8_t>(18, 50)};
    auto r = blendImages8(Blend8Mode::Alpha, src, dst);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    Image8 rgbSrc{2, 2, 3, std::vector<std::uint8_t>(12, 100)};
    Image8 dst2{2, 2, 3, std::vector<std::uint8_t>(12, 200)};
    EXPECT_FALSE(blendImages8(Blend8Mode::Alpha, rgbSrc, dst2).ok());  // alpha needs RGBA src
    auto added = blendImages8(Blend8Mode::Add, rgbSrc, dst2);          // add ignores alpha
    ASSERT_TRUE(added.ok());
    EXPECT_EQ(added->pixels, std::vector<std::uint8_t>(12, 255));
}

TEST(Blend8, ModeNamesRoundTrip) {
    for (auto mode :
         {Blend8Mode::Alpha, Blend8Mode::AlphaShift, Blend8Mode::Premultiplied, Blend8Mode::Add}) {
        EXPECT_EQ(parseBlend8Mode(blend8ModeName(mode)), mode);
    }
    EXPECT_FALSE(parseBlend8Mode("multiply").has_value());
}
