// SPDX-License-Identifier: Apache-2.0
#include "flare/SpriteImages.h"

#include <algorithm>
#include <cmath>

namespace flarekit {

namespace {
//! Largest element texture side: an element of size 4 (its range's top) at 2160p would need
//! 17k texels a side; bigger ones are rendered smaller and magnified (they are soft anyway).
constexpr int kMaxTextureSide = 2048;
}  // namespace

std::vector<SpriteImage> renderSpriteImages(const Preset& preset, int height) {
    std::vector<SpriteImage> sprites;
    for (const ElementParams& e : preset.elements) {
        const float radius = e.size * float(height);
        const float k = e.intensity * preset.intensity;
        if (!e.visible || radius < kMinSpriteRadiusPx || k <= 0.f || !std::isfinite(k)) continue;
        ElementParams scaled = e;
        scaled.intensity = k;
        // Texels per frame pixel: 1 unless the element would exceed the texture limit.
        const float extent = 2.f * radius * std::max(1.f, e.aspect) + 8.f;
        const float texScale = std::min(1.f, float(kMaxTextureSide) / extent);
        Image image = renderElement(scaled, radius * texScale);
        sprites.push_back(
            {{e.t, 0.5f * float(image.width()) / texScale, 0.5f * float(image.height()) / texScale,
              e.blend, e.type == ElementType::EdgeStreak, e.reach},
             std::move(image)});
    }
    return sprites;
}

}  // namespace flarekit
