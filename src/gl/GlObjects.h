// SPDX-License-Identifier: Apache-2.0
// Move-only owners of GL object names: each deletes its name when destroyed. A context must
// be current wherever these are created, used or destroyed.
#pragma once

#include <epoxy/gl.h>

#include "flarekit/gl/GpuTimer.h"

#include <string>
#include <utility>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Vec3.h"

namespace flarekit::gl {

template <void (*Delete)(GLuint)>
class Name {
  public:
    Name() = default;
    explicit Name(GLuint name) : m_name(name) {}
    ~Name() { reset(); }
    Name(Name&& other) noexcept : m_name(std::exchange(other.m_name, 0)) {}
    Name& operator=(Name&& other) noexcept {
        if (this != &other) {
            reset();
            m_name = std::exchange(other.m_name, 0);
        }
        return *this;
    }
    Name(const Name&) = delete;
    Name& operator=(const Name&) = delete;

    GLuint get() const { return m_name; }
    explicit operator bool() const { return m_name != 0; }
    void reset() {
        if (m_name) Delete(m_name);
        m_name = 0;
    }

  private:
    GLuint m_name = 0;
};

namespace detail {
inline void deleteTexture(GLuint n) {
    glDeleteTextures(1, &n);
}
inline void deleteFramebuffer(GLuint n) {
    glDeleteFramebuffers(1, &n);
}
inline void deleteBuffer(GLuint n) {
    glDeleteBuffers(1, &n);
}
inline void deleteVertexArray(GLuint n) {
    glDeleteVertexArrays(1, &n);
}
inline void deleteQuery(GLuint n) {
    glDeleteQueries(1, &n);
}
inline void deleteProgram(GLuint n) {
    glDeleteProgram(n);
}
inline void deleteShader(GLuint n) {
    glDeleteShader(n);
}
}  // namespace detail

using Texture = Name<detail::deleteTexture>;
using Framebuffer = Name<detail::deleteFramebuffer>;
using Buffer = Name<detail::deleteBuffer>;
using VertexArray = Name<detail::deleteVertexArray>;
using Query = Name<detail::deleteQuery>;
using Program = Name<detail::deleteProgram>;
using Shader = Name<detail::deleteShader>;

//! An empty vertex array: what attribute-less draws (full-screen triangles, quads built from
//! gl_VertexID) bind in a core profile.
inline VertexArray makeVertexArray() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name);
}

//! An immutable 2D texture (glTextureStorage2D) of the given internal format.
Texture makeTexture2D(GLenum internalFormat, int width, int height);
//! A framebuffer with texture `color` at attachment 0 (and `depth` when non-zero; either may be
//! multisampled); fails with the completeness status when incomplete.
Result<Framebuffer> makeFramebuffer(GLuint color, GLuint depth = 0);
inline Result<Framebuffer> makeFramebuffer(const Texture& color, const Texture* depth = nullptr) {
    return makeFramebuffer(color.get(), depth ? depth->get() : 0);
}

//! Ok, or "OpenGL: <what> failed (error 0x0502)" when glGetError reports an error.
Status checkError(const std::string& what);

//! Ok when an OpenGL context (EGL, or GLX in a process that has it) is current on this thread;
//! else an error naming `what`. Every GL class's create() asks first: a GL call without a
//! context would end the process in libepoxy's assertion instead of returning an error.
Status requireCurrentContext(const char* what);
//! Whether an OpenGL context (EGL, or GLX in a process that has it) is current on this thread.
bool hasCurrentContext();

//! Level 0 of a width x height colour texture as float RGBA, top row first (GL rows are
//! bottom-up; `flipRows` false keeps GL row 0 as image row 0, for textures uploaded that way).
//! Waits for the GPU. Read in bands, so frames past 2 GiB need no GLsizei > 2^31.
Result<Image> readTextureRgba(GLuint texture, int width, int height, bool flipRows = true);

//! glGetUniformLocation, with a check: a name the program's shader text does not contain (a
//! misspelt uniform, which GL would silently ignore as location -1) is an error that the next
//! checkError() reports, in debug builds and wherever FLAREKIT_STRICT_GL=1 (every GL test).
//! A declared uniform the compiler optimised away stays -1 without an error.
GLint uniformLocation(GLuint program, const char* name);

//! glProgramUniform3f of a (double) Vec3 by uniform name.
inline void setUniform(GLuint program, const char* name, Vec3 v) {
    glProgramUniform3f(program, uniformLocation(program, name), float(v.x), float(v.y), float(v.z));
}

struct ShaderSource {
    GLenum stage;      //!< GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string name;  //!< for error messages, e.g. "ghosts.frag"
    std::string text;
};
//! Compiles and links; a failure returns the first line of the driver's log with the name.
Result<Program> linkProgram(std::initializer_list<ShaderSource> sources);

//! GPU time of the commands between begin() and end(), from GL_TIME_ELAPSED. Reading waits
//! for the GPU to finish them.
using TimerQuery = GpuTimer;

}  // namespace flarekit::gl
