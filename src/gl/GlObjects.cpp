// SPDX-License-Identifier: Apache-2.0
#include "gl/GlObjects.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include <cctype>
#include <cstdlib>
#include <string>
#include <utility>

#include <dlfcn.h>
#include <epoxy/egl.h>

#include "core/FirstLine.h"

namespace flarekit::gl {

Texture makeTexture2D(GLenum internalFormat, int width, int height) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &name);
    glTextureStorage2D(name, 1, internalFormat, width, height);
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return Texture(name);
}

namespace {
std::string hex(GLenum code) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", unsigned(code));
    return buf;
}
}  // namespace

Result<Framebuffer> makeFramebuffer(GLuint color, GLuint depth) {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    Framebuffer fb(name);
    glNamedFramebufferTexture(name, GL_COLOR_ATTACHMENT0, color, 0);
    if (depth) glNamedFramebufferTexture(name, GL_DEPTH_ATTACHMENT, depth, 0);
    const GLenum status = glCheckNamedFramebufferStatus(name, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return internalError("OpenGL: framebuffer incomplete (status " + hex(status) + ")");
    return fb;
}

namespace {

//! The first misspelt uniform since the last checkError() on this thread.
thread_local std::string t_missingUniform;

bool strictUniforms() {
#ifndef NDEBUG
    return true;
#else
    static const bool strict = [] {
        const char* env = std::getenv("FLAREKIT_STRICT_GL");
        return env && std::string(env) == "1";
    }();
    return strict;
#endif
}

//! Whether `identifier` appears as a whole word in the text of a shader attached to `program`.
bool sourcesMention(GLuint program, const std::string& identifier) {
    GLint count = 0;
    glGetProgramiv(program, GL_ATTACHED_SHADERS, &count);
    std::vector<GLuint> attached(std::size_t(std::max(count, 0)));
    if (count > 0) glGetAttachedShaders(program, count, nullptr, attached.data());
    for (GLuint shader : attached) {
        GLint length = 0;
        glGetShaderiv(shader, GL_SHADER_SOURCE_LENGTH, &length);
        std::string text(std::size_t(std::max(length, 1)), '\0');
        glGetShaderSource(shader, length, nullptr, text.data());
        const auto isWord = [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        };
        for (std::size_t at = text.find(identifier); at != std::string::npos;
             at = text.find(identifier, at + 1)) {
            const std::size_t end = at + identifier.size();
            if ((at == 0 || !isWord(text[at - 1])) && (end >= text.size() || !isWord(text[end])))
                return true;
        }
    }
    return false;
}

}  // namespace

GLint uniformLocation(GLuint program, const char* name) {
    const GLint location = glGetUniformLocation(program, name);
    if (location >= 0 || !strictUniforms() || !t_missingUniform.empty()) return location;
    std::string identifier(name);
    identifier = identifier.substr(0, identifier.find_first_of("[."));  // "tints[3]" -> "tints"
    if (!sourcesMention(program, identifier)) t_missingUniform = name;
    return location;
}

Status checkError(const std::string& what) {
    if (!t_missingUniform.empty()) {
        const std::string name = std::exchange(t_missingUniform, {});
        return internalError("OpenGL: " + what + ": the program has no uniform '" + name + "'");
    }
    if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
        return internalError("OpenGL: " + what + " failed (error " + hex(err) + ")");
    }
    return Ok{};
}

Result<Image> readTextureRgba(GLuint texture, int width, int height, bool flipRows) {
    Image image(width, height);  // read straight into it: the frame's pages are touched once
    const std::size_t rowFloats = std::size_t(width) * 4, rowBytes = rowFloats * sizeof(float);
    const int bandRows = int(std::max<std::size_t>(1, (std::size_t(1) << 30) / rowBytes));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int y = 0; y < height; y += bandRows) {
        const int rows = std::min(bandRows, height - y);
        glGetTextureSubImage(texture, 0, 0, y, 0, width, rows, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(rowBytes * std::size_t(rows)), image.row(y));
    }
    if (Status s = checkError("reading a frame back"); !s) return s.error();
    for (int y = 0; flipRows && y < height / 2; ++y)
        std::swap_ranges(image.row(y), image.row(y) + rowFloats, image.row(height - 1 - y));
    return image;
}

namespace {
std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length > 1 ? length : 1), '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
              : glGetShaderInfoLog(object, length, nullptr, log.data());
    return firstLine(log.data());
}
}  // namespace

Result<Program> linkProgram(std::initializer_list<ShaderSource> sources) {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    for (const ShaderSource& s : sources) {
        Shader shader(glCreateShader(s.stage));
        const char* text = s.text.c_str();
        glShaderSource(shader.get(), 1, &text, nullptr);
        glCompileShader(shader.get());
        GLint ok = 0;
        glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
        if (!ok)
            return internalError("OpenGL: " + s.name +
                                 ": compile error: " + infoLog(shader.get(), false));
        glAttachShader(program.get(), shader.get());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.get());
    GLint ok = 0;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) return internalError("OpenGL: link error: " + infoLog(program.get(), true));
    return program;
}

bool hasCurrentContext() {
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) return true;
    // An application on GLX: ask libGL if the process has it (no link-time dependency). GLFW
    // and SDL load libGLX / libGL at run time, local to themselves, so look in those by name
    // (RTLD_NOLOAD: only if already loaded) as well as in the global scope.
    using GetContext = void* (*)();
    if (auto glx = reinterpret_cast<GetContext>(dlsym(RTLD_DEFAULT, "glXGetCurrentContext")))
        if (glx()) return true;
    for (const char* library : {"libGLX.so.0", "libGL.so.1", "libGL.so"}) {
        void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
        if (!handle) continue;
        auto glx = reinterpret_cast<GetContext>(dlsym(handle, "glXGetCurrentContext"));
        const bool current = glx && glx();
        dlclose(handle);
        if (current) return true;
    }
    return false;
}

Status requireCurrentContext(const char* what) {
    if (hasCurrentContext()) return Ok{};
    return invalidInput(std::string(what) +
                        ": no OpenGL context is current on this thread (make one current, e.g. "
                        "with flarekit::gl::HeadlessGl::create())");
}

}  // namespace flarekit::gl

namespace flarekit {

// Two GL_TIMESTAMP queries rather than one GL_TIME_ELAPSED: Mesa's llvmpipe leaves compute
// dispatches out of elapsed-time queries and reports a first draw's as hours, while its
// timestamps bracket the work; GPU drivers give the same figure either way.
GpuTimer::GpuTimer() {
    glCreateQueries(GL_TIMESTAMP, 2, m_queries);
}
GpuTimer::~GpuTimer() {
    if (m_queries[0]) glDeleteQueries(2, m_queries);
}
GpuTimer& GpuTimer::operator=(GpuTimer&& other) noexcept {
    if (this != &other) {
        if (m_queries[0]) glDeleteQueries(2, m_queries);
        m_queries[0] = std::exchange(other.m_queries[0], 0u);
        m_queries[1] = std::exchange(other.m_queries[1], 0u);
    }
    return *this;
}
void GpuTimer::begin() const {
    glQueryCounter(m_queries[0], GL_TIMESTAMP);
}
void GpuTimer::end() const {
    glQueryCounter(m_queries[1], GL_TIMESTAMP);
}
double GpuTimer::milliseconds() const {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(m_queries[0], GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(m_queries[1], GL_QUERY_RESULT, &end);
    return end > start ? double(end - start) * 1e-6 : 0.0;
}

}  // namespace flarekit
