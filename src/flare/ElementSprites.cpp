// SPDX-License-Identifier: Apache-2.0
#include "flare/ElementSprites.h"

namespace flarekit {

Result<std::vector<ElementSprite>> buildElementSprites(const Preset& preset, int height) {
    std::vector<ElementSprite> sprites;
    for (const SpriteImage& s : renderSpriteImages(preset, height)) {
        const Image& image = s.image;
        ElementSprite sprite{s, gl::makeTexture2D(GL_RGBA16F, image.width(), image.height())};
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
