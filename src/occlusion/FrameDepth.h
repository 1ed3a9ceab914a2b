// SPDX-License-Identifier: Apache-2.0
// A program that reads the main frame's depth through shaders/frame_depth.glsl, linked for
// both kinds of frame: single-sample (the depth texture) and multisampled (the MSAA depth plus
// where its samples sit in a pixel, so the shader can point-sample the depth finer than a
// pixel). Passes pick the variant for the renderer's frame each time they draw.
#pragma once

#include <array>
#include <initializer_list>

#include "flarekit/gl/Render.h"
#include "gl/GlObjects.h"

namespace flarekit::occlusion {

class FrameDepthProgram {
  public:
    //! Links `sources` with the sun_disc.glsl and frame_depth.glsl preludes, twice.
    static Result<FrameDepthProgram> link(std::initializer_list<gl::ShaderSource> sources);
    //! The variant for `renderer`'s frame, to set uniforms on and draw with.
    GLuint forFrame(const SceneRenderer& renderer) const {
        return m_variants[renderer.msaaSamples() > 1].get();
    }
    //! Binds `renderer`'s depth to texture unit 0 and, with MSAA, sets forFrame(renderer)'s
    //! sample count and sample positions.
    void bindDepth(const SceneRenderer& renderer) const;

  private:
    std::array<gl::Program, 2> m_variants;  //!< single-sample frame, multisampled frame
};

}  // namespace flarekit::occlusion
