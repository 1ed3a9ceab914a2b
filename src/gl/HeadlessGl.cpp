#include "flarekit/HeadlessGl.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace flarekit::gl {

namespace {

std::string eglErrorText(EGLint code) {
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

//! Tries to make a 4.5 core context current on `display`; returns it or EGL_NO_CONTEXT.
EGLContext makeCoreContext(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
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
    if (context == EGL_NO_CONTEXT) return EGL_NO_CONTEXT;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

}  // namespace

Result<std::unique_ptr<HeadlessGl>> HeadlessGl::create() {
    const char* forced = std::getenv("FLAREKIT_EGL_PLATFORM");
    const bool tryDevice = !forced || std::strcmp(forced, "device") == 0;
    const bool trySurfaceless = !forced || std::strcmp(forced, "surfaceless") == 0;
    std::unique_ptr<HeadlessGl> gl(new HeadlessGl);
    std::string tried;

    if (tryDevice && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(std::size_t(count > 0 ? count : 0));
        if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
        for (EGLDeviceEXT device : devices) {
            EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (display == EGL_NO_DISPLAY) continue;
            if (EGLContext context = makeCoreContext(display); context != EGL_NO_CONTEXT) {
                gl->m_display = display;
                gl->m_context = context;
                gl->m_platform = "device";
                break;
            }
            eglTerminate(display);
        }
        tried += "EGL devices (" + std::to_string(count) + ")";
    }
    if (!gl->m_context && trySurfaceless &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY) {
            if (EGLContext context = makeCoreContext(display); context != EGL_NO_CONTEXT) {
                gl->m_display = display;
                gl->m_context = context;
                gl->m_platform = "surfaceless";
            } else {
                eglTerminate(display);
            }
        }
        tried += std::string(tried.empty() ? "" : ", ") + "Mesa surfaceless";
    }
    if (!gl->m_context) {
        return internalError(
            "OpenGL: no EGL display gave a 4.5 core context (tried " +
            (tried.empty() ? std::string("nothing: no EGL platform extension") : tried) +
            ", last " + eglErrorText(eglGetError()) +
            "); install libegl-mesa0 and libgl1-mesa-dri");
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

}  // namespace flarekit::gl
