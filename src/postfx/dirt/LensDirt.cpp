// SPDX-License-Identifier: Apache-2.0
// Procedural lens dirt, so no asset is required: dust specks (small soft discs with a slightly
// brighter rim, the way out-of-focus dust on a front element looks) and a few large faint
// smudges (grease), placed by a seeded SplitMix64. Each spot is splatted over its bounding box
// only, so the cost is the area the spots cover, not spots x pixels. Values are clamped to
// [0, 1] in all three channels (grey); alpha 0. Generated on the CPU for both backends: the GL
// chain uploads it like a loaded dirt texture.
#include <algorithm>
#include <cmath>

#include "core/Random.h"
#include "flarekit/PostFx.h"

namespace flarekit {

namespace {

struct Spot {
    float x, y, radius, brightness, rim;
};

//! Smudges per speck: a few large ones for every dozen specks, as on a real front element.
constexpr int kSpecksPerSmudge = 10;

void splat(Image& dirt, const Spot& s) {
    const int x0 = std::max(0, int(std::floor(s.x - s.radius))),
              x1 = std::min(dirt.width() - 1, int(std::ceil(s.x + s.radius)));
    const int y0 = std::max(0, int(std::floor(s.y - s.radius))),
              y1 = std::min(dirt.height() - 1, int(std::ceil(s.y + s.radius)));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const float dx = (float(x) + 0.5f - s.x) / s.radius,
                        dy = (float(y) + 0.5f - s.y) / s.radius;
            const float d2 = dx * dx + dy * dy;
            if (d2 >= 1.f) continue;
            const float body = (1.f - d2) * (1.f - d2);  // soft disc
            const float rim =
                std::exp(-(1.f - d2) * 12.f) * (1.f - d2) * 4.f;  // bright edge near d = 1
            Rgba& p = dirt.at(x, y);
            p.r += s.brightness * (body + s.rim * rim);
        }
    }
}

}  // namespace

Image makeLensDirt(int width, int height, const DirtParams& params) {
    Image dirt(std::max(1, width), std::max(1, height));
    SplitMix64 random(params.seed);
    const float size = float(std::max(dirt.width(), dirt.height()));
    const int smudges = params.spots / kSpecksPerSmudge;
    for (int i = 0; i < params.spots + smudges; ++i) {
        const bool smudge = i >= params.spots;
        Spot s{};
        s.x = random.nextFloat() * float(dirt.width());
        s.y = random.nextFloat() * float(dirt.height());
        // Specks 0.4-3% of the frame's long side, smudges 8-20%: dust vs fingerprints.
        s.radius = size * (smudge ? 0.08f + 0.12f * random.nextFloat()
                                  : 0.004f + 0.026f * random.nextFloat());
        s.brightness =
            smudge ? 0.05f + 0.1f * random.nextFloat() : 0.2f + 0.8f * random.nextFloat();
        s.rim = smudge ? 0.f : random.nextFloat();
        s.radius = std::max(s.radius, 1.f);
        splat(dirt, s);
    }
    for (int y = 0; y < dirt.height(); ++y) {
        for (int x = 0; x < dirt.width(); ++x) {
            Rgba& p = dirt.at(x, y);
            p.r = p.g = p.b = std::min(1.f, p.r);
        }
    }
    return dirt;
}

}  // namespace flarekit
