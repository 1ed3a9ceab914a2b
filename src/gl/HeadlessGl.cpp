// SPDX-License-Identifier: Apache-2.0
#include "flarekit/gl/HeadlessGl.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace flarekit::gl {

namespace {

//! The EGL error's name (EGL 1.5 table 3.1), e.g. "EGL_BAD_MATCH".
std::string eglErrorText(EGLint code) {
    static constexpr const char* kNames[] = {
        "EGL_SUCCESS",       "EGL_NOT_INITIALIZED",     "EGL_BAD_ACCESS",
        "EGL_BAD_ALLOC",     "EGL_BAD_ATTRIBUTE",       "EGL_BAD_CONFIG",
        "EGL_BAD_CONTEXT",   "EGL_BAD_CURRENT_SURFACE", "EGL_BAD_DISPLAY",
        "EGL_BAD_MATCH",     "EGL_BAD_NATIVE_PIXMAP",   "EGL_BAD_NATIVE_WINDOW",
        "EGL_BAD_PARAMETER", "EGL_BAD_SURFACE",         "EGL_CONTEXT_LOST"};
    if (code >= EGL_SUCCESS && code <= EGL_CONTEXT_LOST) return kNames[code - EGL_SUCCESS];
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04X", unsigned(code));
    return buf;
}

#ifndef NDEBUG
void GLAPIENTRY logGlMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                             const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::fprintf(stderr, "flarekit: GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "message",
                 message);
}
#endif

//! Tries to make a 4.5 core context current on `display`; returns it or EGL_NO_CONTEXT with
//! `why` saying which step failed and EGL's error.
EGLContext makeCoreContext(EGLDisplay display, std::string& why) {
    auto failed = [&](const char* step) {
        why = std::string(step) + " failed (" + eglErrorText(eglGetError()) + ")";
        return EGL_NO_CONTEXT;
    };
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return failed("eglInitialize");
    if (!eglBindAPI(EGL_OPENGL_API)) return failed("eglBindAPI(OpenGL)");
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
#ifndef NDEBUG
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     EGL_TRUE,
#endif
                                     EGL_NONE};
    // No surface is ever drawn to (every pass renders into framebuffer objects), so no config
    // is needed: EGL_KHR_no_config_context.
    EGLContext context =
        eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return failed("eglCreateContext(4.5 core)");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        failed("eglMakeCurrent");
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

}  // namespace

Result<std::unique_ptr<HeadlessGl>> HeadlessGl::create() {
    const char* forced = std::getenv("FLAREKIT_EGL_PLATFORM");
    if (forced && std::strcmp(forced, "device") != 0 && std::strcmp(forced, "surfaceless") != 0) {
        return invalidInput(
            std::string("FLAREKIT_EGL_PLATFORM: expected device or surfaceless, got '") + forced +
            "'");
    }
    const bool tryDevice = !forced || std::strcmp(forced, "device") == 0;
    const bool trySurfaceless = !forced || std::strcmp(forced, "surfaceless") == 0;
    std::unique_ptr<HeadlessGl> gl(new HeadlessGl);
    std::vector<std::string> attempts;  // "what was tried: what failed", in order

    if (tryDevice && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(std::size_t(count > 0 ? count : 0));
        if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
        if (count <= 0) attempts.push_back("EGL devices: none found");
        for (EGLint i = 0; i < count && !gl->m_context; ++i) {
            const std::string name =
                "EGL device " + std::to_string(i + 1) + " of " + std::to_string(count);
            EGLDisplay display =
                eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
            if (display == EGL_NO_DISPLAY) {
                attempts.push_back(name + ": no display (" + eglErrorText(eglGetError()) + ")");
                continue;
            }
            std::string why;
            if (EGLContext context = makeCoreContext(display, why); context != EGL_NO_CONTEXT) {
                gl->m_display = display;
                gl->m_context = context;
                gl->m_platform = "device";
                break;
            }
            attempts.push_back(name + ": " + why);
            eglTerminate(display);
        }
    } else if (tryDevice) {
        attempts.push_back("EGL devices: no EGL_EXT_platform_device");
    }
    if (!gl->m_context && trySurfaceless &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        std::string why = "no display (" + eglErrorText(eglGetError()) + ")";
        if (display != EGL_NO_DISPLAY) {
            if (EGLContext context = makeCoreContext(display, why); context != EGL_NO_CONTEXT) {
                gl->m_display = display;
                gl->m_context = context;
                gl->m_platform = "surfaceless";
            } else {
                eglTerminate(display);
            }
        }
        if (!gl->m_context) attempts.push_back("Mesa surfaceless: " + why);
    } else if (!gl->m_context && trySurfaceless) {
        attempts.push_back("Mesa surfaceless: no EGL_MESA_platform_surfaceless");
    }
    if (!gl->m_context) {
        std::string tried;
        for (const std::string& a : attempts) tried += (tried.empty() ? "" : "; ") + a;
        return internalError(
            "OpenGL: no headless 4.5 core context (" + tried +
            "): install libegl-mesa0 and libgl1-mesa-dri, or a GPU driver with EGL");
    }
#ifndef NDEBUG
    glEnable(GL_DEBUG_OUTPUT);
    glDebugMessageCallback(logGlMessage, nullptr);
#endif
    return gl;
}

HeadlessGl::~HeadlessGl() {
    if (!m_display) return;
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
    eglTerminate(m_display);
}

std::string HeadlessGl::renderer() const {
    return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}
std::string HeadlessGl::version() const {
    return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}
bool HeadlessGl::software() const {
    const std::string name = renderer();
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

}  // namespace flarekit::gl
