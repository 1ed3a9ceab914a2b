// SPDX-License-Identifier: Apache-2.0
// What the GPU visibility methods share: the 1x1 R32F coverage texture they write, programs
// with the sun_disc.glsl prelude, a full-screen triangle, and error checks.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "flarekit/gl/GpuVisibility.h"
#include "gl/GlObjects.h"
#include "occlusion/SunDisc.h"

namespace flarekit::occlusion {

class GpuMethod : public GpuVisibility {
  public:
    GpuMethod();
    GpuChannel coverage() const override { return {m_coverage.get(), 0}; }
    std::optional<double> latestCoverage() override;

  protected:
    //! Stores a CPU-side result in the coverage texture (read-back methods).
    void publish(double coverage);
    //! Binds the coverage texture as image unit 0 / a draw target for GPU-side results.
    GLuint coverageName() const { return m_coverage.get(); }
    void markPublished() { m_hasResult = true; }

  private:
    gl::Texture m_coverage;
    bool m_hasResult = false;
};

//! A width x height texture's level 0 read back as RGBA floats, its top row first (GL's rows
//! run bottom-up), named `name`: a MethodView.
MethodView readMethodView(GLuint texture, int width, int height, std::string name);

//! Links a program whose shaders get "#version 450 core", `defines` (e.g. "#define X\n") and
//! the sun_disc.glsl prelude.
Result<gl::Program> linkWithDisc(std::initializer_list<gl::ShaderSource> sources,
                                 const std::string& defines = "");
//! A full-screen-triangle program (fullscreen.vert) with the given fragment shader, with
//! `defines` after its #version line and without the disc prelude.
Result<gl::Program> linkFullscreen(const std::string& fragmentName, const char* fragmentText,
                                   const std::string& defines = "");

}  // namespace flarekit::occlusion
