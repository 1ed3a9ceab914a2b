// SPDX-License-Identifier: Apache-2.0
// The post-process test images: a single bright dot, several lights, an HDR sky
// with a sun of value 50, and noise. Built in code, so the tests carry no binary fixtures.
#pragma once

#include <cmath>
#include <cstdint>

#include "flarekit/Image.h"

namespace flarekit::test {

//! A black image with a disc of `value` (white) of the given radius at (cx, cy) in pixels.
inline Image brightDot(int w, int h, float cx, float cy, float value, float radius = 2.f) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
            if (dx * dx + dy * dy <= radius * radius)
                img.at(x, y) = {value, value, value, 1.f};
            else
                img.at(x, y).a = 1.f;
        }
    }
    return img;
}

//! Five coloured lights of different sizes and values over a dim grey background.
inline Image severalLights(int w, int h) {
    Image img(w, h);
    img.fill({0.05f, 0.05f, 0.06f, 1.f});
    const struct {
        float x, y, r, red, green, blue;
    } lights[] = {
        {0.2f, 0.25f, 0.02f, 8.f, 6.f, 3.f},   {0.8f, 0.3f, 0.012f, 20.f, 20.f, 20.f},
        {0.55f, 0.7f, 0.03f, 2.f, 4.f, 9.f},   {0.1f, 0.85f, 0.008f, 40.f, 10.f, 5.f},
        {0.93f, 0.92f, 0.015f, 5.f, 5.f, 5.f},
    };
    for (const auto& l : lights) {
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const float dx = (float(x) + 0.5f) / float(w) - l.x,
                            dy = ((float(y) + 0.5f) / float(h) - l.y) * float(h) / float(w);
                if (dx * dx + dy * dy <= l.r * l.r) img.at(x, y) = {l.red, l.green, l.blue, 1.f};
            }
        }
    }
    return img;
}

//! A sky gradient (0.2 .. 1.2) with a sun disc of value 50 and its glow, and dark ground.
inline Image hdrSky(int w, int h, float sunX = 0.7f, float sunY = 0.3f) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float u = (float(x) + 0.5f) / float(w), v = (float(y) + 0.5f) / float(h);
            const float dx = (u - sunX) * float(w) / float(h), dy = v - sunY,
                        d = std::sqrt(dx * dx + dy * dy);
            Rgba p{0.3f + 0.9f * (1.f - v), 0.4f + 0.7f * (1.f - v), 0.9f + 0.3f * (1.f - v), 1.f};
            const float glow = 2.f * std::exp(-d * 12.f);
            p.r += glow, p.g += glow * 0.9f, p.b += glow * 0.7f;
            if (d < 0.03f) p = {50.f, 48.f, 44.f, 1.f};
            if (v > 0.75f + 0.03f * std::sin(u * 20.f)) p = {0.02f, 0.02f, 0.025f, 1.f};
            img.at(x, y) = p;
        }
    }
    return img;
}

//! Uniform noise in [0, 4): many small "lights" everywhere above and below the threshold.
inline Image noiseImage(int w, int h, std::uint32_t seed = 1) {
    Image img(w, h);
    std::uint32_t s = seed * 2654435761u + 1u;
    for (std::size_t i = 0; i < img.pixelCount() * 4; ++i) {
        s ^= s << 13, s ^= s >> 17, s ^= s << 5;  // xorshift32 (Marsaglia 2003)
        img.data()[i] = (i % 4 == 3) ? 1.f : float(s >> 8) * (4.f / 16777216.f);
    }
    return img;
}

}  // namespace flarekit::test
