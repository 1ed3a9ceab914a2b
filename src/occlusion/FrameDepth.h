// Binds the main frame's depth for shaders built with shaders/frame_depth.glsl: the
// single-sample depth, or with MSAA the multisampled depth plus where its samples sit in a
// pixel, so those shaders can point-sample the depth finer than a pixel.
#pragma once

#include <initializer_list>
#include <string>

#include "flarekit/Render.h"
#include "gl/GlObjects.h"

namespace flarekit::occlusion {

//! Links `sources` with the sun_disc.glsl and frame_depth.glsl preludes, for frames with
//! (multisample) or without MSAA.
Result<gl::Program> linkWithFrameDepth(std::initializer_list<gl::ShaderSource> sources, bool multisample);

//! Binds `renderer`'s depth to texture unit 0 and, with MSAA, sets `program`'s sample count and
//! sample positions. The program must be the one linked for renderer.msaaSamples() > 1.
void bindFrameDepth(GLuint program, const SceneRenderer& renderer);

}  // namespace flarekit::occlusion
