// SPDX-License-Identifier: Apache-2.0
// Per-pixel sky fraction under the sun's disc (shaders/sky_fraction.frag): what the read-back
// methods copy to the CPU when the frame is multisampled, so their estimate sees occluder
// edges to a sample, not a pixel.
#pragma once

#include "flarekit/gl/Render.h"
#include "gl/GlObjects.h"
#include "occlusion/SunDisc.h"

namespace flarekit::occlusion {

class SkyFraction {
  public:
    static Result<SkyFraction> create();
    //! Fills the disc's pixel box of a frame-sized R32F target from `renderer`'s depth samples;
    //! the framebuffer to read it from (GL_RED, GL_FLOAT).
    Result<GLuint> update(const SunDiscView& v, const SceneRenderer& renderer);

  private:
    gl::Program m_multisample, m_single;
    gl::VertexArray m_vao;
    gl::Texture m_texture;
    gl::Framebuffer m_target;
    int m_width = 0, m_height = 0;
};

}  // namespace flarekit::occlusion
