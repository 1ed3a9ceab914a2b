// SPDX-License-Identifier: Apache-2.0
#include "flare/ElementSprites.h"

#include <algorithm>
#include <cmath>

namespace flarekit {

namespace {
//! Largest element texture side: an element of size 4 (its range's top) at 2160p would need
//! 17k texels a side; bigger ones are rendered smaller and magnified (they are soft anyway).
constexpr int kMaxTextureSide = 2048;
}  // namespace

Result<std::vector<ElementSprite>> buildElementSprites(const Preset& preset, int height) {
    std::vector<ElementSprite> sprites;
    for (const ElementParams& e : preset.elements) {
        const float radius = e.size * float(height);
        const float k = e.intensity * preset.intensity;
        if (!e.visible || radius < kMinSpriteRadiusPx || k <= 0.f || !std::isfinite(k)) continue;
        ElementParams scaled = e;
        scaled.intensity = k;
        // Texels per frame pixel: 1 unless the element would exceed the texture limit.
        const float extent = 2.f * radius * std::max(1.f, e.aspect) + 8.f;
        const float texScale = std::min(1.f, float(kMaxTextureSide) / extent);
        const Image image = renderElement(scaled, radius * texScale);
        ElementSprite sprite{e.t,
                             0.5f * float(image.width()) / texScale,
                             0.5f * float(image.height()) / texScale,
                             e.blend,
                             e.type == ElementType::EdgeStreak,
                             e.reach,
                             gl::makeTexture2D(GL_RGBA16F, image.width(), image.height())};
        const GLuint tex = sprite.texture.get();
        glTextureSubImage2D(tex, 0, 0, 0, image.width(), image.height(), GL_RGBA, GL_FLOAT,
                            image.data());
        glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        const float transparent[4] = {0.f, 0.f, 0.f, 0.f};
        glTextureParameterfv(tex, GL_TEXTURE_BORDER_COLOR, transparent);
        sprites.push_back(std::move(sprite));
    }
    if (Status s = gl::checkError("uploading the flare's element textures"); !s) return s.error();
    return sprites;
}

}  // namespace flarekit
