// SPDX-License-Identifier: Apache-2.0
// A move-only RGBA8 texture for the panels: the previews and thumbnails the CPU made, shown by
// Dear ImGui. A GL context must be current.
#pragma once

#include <epoxy/gl.h>
#include <imgui.h>

#include <cstdint>
#include <utility>

#include "flarekit/Image.h"

namespace flarekit::studio {

class GlTexture {
  public:
    GlTexture() = default;
    ~GlTexture() {
        if (m_id) glDeleteTextures(1, &m_id);
    }
    GlTexture(GlTexture&& o) noexcept : m_id(std::exchange(o.m_id, 0)), m_w(o.m_w), m_h(o.m_h) {}
    GlTexture& operator=(GlTexture&& o) noexcept {
        std::swap(m_id, o.m_id), std::swap(m_w, o.m_w), std::swap(m_h, o.m_h);
        return *this;
    }
    GlTexture(const GlTexture&) = delete;
    GlTexture& operator=(const GlTexture&) = delete;

    //! The pixels (4 channels), replacing what was there; the name stays the same. `nearest`:
    //! magnified as blocks (a 16x16 sun map shows its texels), else bilinear.
    void upload(const Image8& image, bool nearest = false) {
        if (!m_id) glGenTextures(1, &m_id);
        glBindTexture(GL_TEXTURE_2D, m_id);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (image.width != m_w || image.height != m_h) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, image.pixels.data());
            const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            m_w = image.width, m_h = image.height;
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_w, m_h, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.pixels.data());
        }
    }
    bool valid() const { return m_id != 0; }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(std::uintptr_t(m_id)); }
    int width() const { return m_w; }
    int height() const { return m_h; }

  private:
    GLuint m_id = 0;
    int m_w = 0, m_h = 0;
};

}  // namespace flarekit::studio
