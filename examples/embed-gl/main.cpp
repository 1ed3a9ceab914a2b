// SPDX-License-Identifier: Apache-2.0
// embed-gl: a small OpenGL application with its own context, shaders, city of street lamps,
// reversed-Z MSAA depth buffer and render loop, which gets lens flares from flarekit through
// the C API alone: each frame it hands flarekit its depth texture, matrices and lights
// (fk_engine_occlusion: one batched GPU pass), then has every light's flare added to its HDR
// colour before its own tone map (fk_engine_draw).
//   embed-gl [--frames N] [--size WxH] [--out frame.ppm] [--scene-json S] [--coverage-json C]
//            [--window | --headless]
// With a display (and GLFW) it opens a window and runs until it is closed (or --frames N
// frames); --headless, or no display, renders N frames (default 3) off screen. Either way the
// last frame goes to --out.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#if EMBED_HAS_GLFW
#include <GLFW/glfw3.h>
#endif

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "CityMesh.h"
#include "flarekit/flarekit.h"

namespace {

//! Reversed-Z with an infinite far plane, for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE):
//! near maps to depth 1, infinity to 0.
Mat reversedInfinitePerspective(float fovYDeg, float aspect, float nearPlane) {
    const float f = 1.f / std::tan(fovYDeg * 3.14159265f / 360.f);
    return {f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, 0, -1, 0, 0, nearPlane, 0};
}

GLuint compile(GLenum stage, const char* text) {
    const GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        std::fprintf(stderr, "embed-gl: shader: %s\n", log);
        std::exit(1);
    }
    return s;
}

GLuint program(const char* vert, const char* frag) {
    const GLuint p = glCreateProgram();
    glAttachShader(p, compile(GL_VERTEX_SHADER, vert));
    glAttachShader(p, compile(GL_FRAGMENT_SHADER, frag));
    glLinkProgram(p);
    return p;
}

const char* kSceneVert = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;  // a = 1: emissive (a lamp's bulb)
uniform mat4 viewProjection;
out vec3 n;
out vec4 c;
void main() { n = normal; c = color; gl_Position = viewProjection * vec4(position, 1.0); })";
const char* kSceneFrag = R"(#version 450 core
in vec3 n;
in vec4 c;
uniform vec3 sunDirection;
out vec4 fragColor;
void main() {
    vec3 lit = c.rgb * (6.0 * max(dot(normalize(n), sunDirection), 0.0) + vec3(0.25, 0.3, 0.4));
    fragColor = vec4(c.a > 0.5 ? c.rgb : lit, 1.0);
})";
const char* kFullscreenVert = R"(#version 450 core
out vec2 ndc;
void main() { ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
              gl_Position = vec4(ndc, 0.0, 1.0); })";
const char* kSkyFrag = R"(#version 450 core
in vec2 ndc;
uniform vec3 right, up, forward;  // the camera's basis
uniform vec2 tanHalf;             // tan(fov / 2) across and up
uniform vec3 sunDirection;
uniform float cosSunRadius;
out vec4 fragColor;
void main() {
    vec3 d = normalize(forward + right * (ndc.x * tanHalf.x) + up * (ndc.y * tanHalf.y));
    vec3 sky = mix(vec3(0.9, 0.6, 0.4), vec3(0.15, 0.25, 0.55), clamp(d.y * 3.0, 0.0, 1.0));
    fragColor = vec4(dot(d, sunDirection) >= cosSunRadius ? vec3(3000.0, 2600.0, 2000.0) : sky, 1.0);
})";
const char* kTonemapFrag = R"(#version 450 core
in vec2 ndc;
layout(binding = 0) uniform sampler2D hdr;
out vec4 fragColor;
void main() {
    vec3 x = texture(hdr, ndc * 0.5 + 0.5).rgb * 0.6;
    vec3 mapped = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);  // Narkowicz's ACES fit
    fragColor = vec4(pow(clamp(mapped, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
})";

bool headlessContext() {
    EGLDisplay display = EGL_NO_DISPLAY;
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) && count > 0)
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
    }
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr) &&
            eglBindAPI(EGL_OPENGL_API)) {
            const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
            EGLContext ctx = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
            if (ctx != EGL_NO_CONTEXT &&
                eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
                return true;
        }
        display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }
    return false;
}

struct Options {
    int frames = 3, width = 1280, height = 720;
    std::string out = "embed-gl.ppm", sceneJson, coverageJson;
    bool window = false, headless = false, framesGiven = false;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--frames" && more)
            o.frames = std::atoi(argv[++i]), o.framesGiven = true;
        else if (a == "--size" && more) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2) return false;
        } else if (a == "--out" && more)
            o.out = argv[++i];
        else if (a == "--scene-json" && more)
            o.sceneJson = argv[++i];
        else if (a == "--coverage-json" && more)
            o.coverageJson = argv[++i];
        else if (a == "--window")
            o.window = true;
        else if (a == "--headless")
            o.headless = true;
        else
            return false;
    }
    return !(o.window && o.headless) && o.frames >= 1 && o.width >= 16 && o.height >= 16 &&
           o.width <= 8192 && o.height <= 8192;
}

GLuint texture(GLenum target, GLenum format, int w, int h, int samples) {
    GLuint t = 0;
    glCreateTextures(target, 1, &t);
    if (target == GL_TEXTURE_2D_MULTISAMPLE)
        glTextureStorage2DMultisample(t, samples, format, w, h, GL_TRUE);
    else
        glTextureStorage2D(t, 1, format, w, h);
    return t;
}

GLuint framebuffer(GLuint color, GLuint depth) {
    GLuint f = 0;
    glCreateFramebuffers(1, &f);
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT0, color, 0);
    if (depth) glNamedFramebufferTexture(f, GL_DEPTH_ATTACHMENT, depth, 0);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr,
                     "usage: embed-gl [--frames N] [--size WxH] [--out F.ppm] "
                     "[--scene-json S] [--coverage-json C] [--window | --headless]\n");
        return 2;
    }
#if EMBED_HAS_GLFW
    GLFWwindow* window = nullptr;
    // A display and no --headless: a window, as an application would open.
    const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY");
    const bool asked = o.window;
    if (!o.headless && display) o.window = true;
    if (o.window && !glfwInit()) {
        if (asked) return std::fprintf(stderr, "embed-gl: no display for --window\n"), 2;
        o.window = false;  // a display that does not answer: off screen instead
    }
    if (o.window) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        window = glfwCreateWindow(o.width, o.height, "flarekit embed-gl", nullptr, nullptr);
        if (!window) return std::fprintf(stderr, "embed-gl: no GL 4.5 window\n"), 1;
        glfwMakeContextCurrent(window);
        std::printf("embed-gl: a %dx%d window (GLFW)\n", o.width, o.height);
    }
#else
    if (o.window) return std::fprintf(stderr, "embed-gl: built without GLFW\n"), 2;
#endif
    if (!o.window && !headlessContext())
        return std::fprintf(stderr, "embed-gl: no EGL context\n"), 1;

    const City city = makeCity();
    std::vector<Vertex> mesh;
    for (const CityBox& b : city.boxes) pushBox(mesh, b);
    pushBox(mesh, {{-2000, -1, -2000}, {2000, 0, 2000}, {0.25f, 0.25f, 0.27f}});  // the ground
    for (const Lamp& l : city.lamps) pushBulb(mesh, l);
    GLuint vbo = 0, vao = 0, empty = 0;
    glCreateBuffers(1, &vbo);
    glNamedBufferStorage(vbo, GLsizeiptr(mesh.size() * sizeof(Vertex)), mesh.data(), 0);
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(Vertex));
    const GLint sizes[3] = {3, 3, 4};
    const GLuint offsets[3] = {0, 12, 24};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    glCreateVertexArrays(1, &empty);
    const GLuint sceneProgram = program(kSceneVert, kSceneFrag);
    const GLuint skyProgram = program(kFullscreenVert, kSkyFrag);
    const GLuint tonemapProgram = program(kFullscreenVert, kTonemapFrag);

    // Targets: 4x MSAA HDR colour + reversed-Z depth, resolved HDR colour, display colour.
    const int w = o.width, h = o.height;
    const GLuint msColor = texture(GL_TEXTURE_2D_MULTISAMPLE, GL_RGBA16F, w, h, 4);
    const GLuint msDepth = texture(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_COMPONENT32F, w, h, 4);
    const GLuint hdr = texture(GL_TEXTURE_2D, GL_RGBA16F, w, h, 1);
    const GLuint ldr = texture(GL_TEXTURE_2D, GL_RGBA8, w, h, 1);
    const GLuint msTarget = framebuffer(msColor, msDepth), hdrTarget = framebuffer(hdr, 0),
                 ldrTarget = framebuffer(ldr, 0);

    // flarekit: one engine, a preset for the sun and one for the lamps, every light.
    fk_engine* flares = fk_engine_create(int(city.lamps.size()) + 1);
    if (!flares) return std::fprintf(stderr, "embed-gl: %s\n", fk_error(nullptr)), 1;
    const int sunPreset = fk_engine_load_preset(flares, "tanczos-classic");
    const int lampPreset = fk_engine_load_preset(flares, "subtle");
    if (sunPreset < 0 || lampPreset < 0)
        return std::fprintf(stderr, "embed-gl: %s\n", fk_error(flares)), 1;
    const V3 sun = sunToward(city);
    const std::vector<fk_light> lights = cityLights(city, sunPreset, lampPreset);

    City view = city;
    // A window runs until closed unless --frames was given.
    for (int frame = 0; frame < o.frames || (o.window && !o.framesGiven); ++frame) {
#if EMBED_HAS_GLFW
        if (window && glfwWindowShouldClose(window)) break;
#endif
        view.eye.z = city.eye.z - 0.15f * float(frame);  // walking down the street
        const Mat v = lookAt(view.eye, view.target);
        const Mat p =
            reversedInfinitePerspective(view.fovYDeg, float(w) / float(h), view.nearPlane);
        const Mat vp = multiply(p, v);
        // The application's own passes: sky, then the city with reversed-Z depth.
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        glBindFramebuffer(GL_FRAMEBUFFER, msTarget);
        glViewport(0, 0, w, h);
        glClearDepth(0.0);
        glDepthMask(GL_TRUE);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(skyProgram);
        // The camera basis is the view matrix's rows; the sky shader builds each pixel's ray.
        glUniform3f(glGetUniformLocation(skyProgram, "right"), v[0], v[4], v[8]);
        glUniform3f(glGetUniformLocation(skyProgram, "up"), v[1], v[5], v[9]);
        glUniform3f(glGetUniformLocation(skyProgram, "forward"), -v[2], -v[6], -v[10]);
        const float tanHalfY = std::tan(view.fovYDeg * 3.14159265f / 360.f);
        glUniform2f(glGetUniformLocation(skyProgram, "tanHalf"), tanHalfY * float(w) / float(h),
                    tanHalfY);
        glUniform3f(glGetUniformLocation(skyProgram, "sunDirection"), sun.x, sun.y, sun.z);
        glUniform1f(glGetUniformLocation(skyProgram, "cosSunRadius"),
                    std::cos(city.sunRadiusDeg * 3.14159265f / 180.f));
        glBindVertexArray(empty);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glUseProgram(sceneProgram);
        glUniformMatrix4fv(glGetUniformLocation(sceneProgram, "viewProjection"), 1, GL_FALSE,
                           vp.data());
        glUniform3f(glGetUniformLocation(sceneProgram, "sunDirection"), sun.x, sun.y, sun.z);
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(mesh.size()));
        glDisable(GL_DEPTH_TEST);
        glBlitNamedFramebuffer(msTarget, hdrTarget, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);

        // flarekit: every light measured in the MSAA depth, then drawn into the HDR colour.
        fk_frame f{};
        f.depth_texture = msDepth;
        f.width = w, f.height = h;
        f.viewport[0] = 0, f.viewport[1] = 0, f.viewport[2] = w, f.viewport[3] = h;
        f.depth_convention = FK_DEPTH_REVERSED_Z;
        std::memcpy(f.view, v.data(), sizeof f.view);
        std::memcpy(f.projection, p.data(), sizeof f.projection);
        f.dt_seconds = 1.f / 60.f;
        if (fk_engine_occlusion(flares, &f, lights.data(), int(lights.size())) < 0 ||
            fk_engine_draw(flares, &f, lights.data(), int(lights.size()), hdrTarget) < 0)
            return std::fprintf(stderr, "embed-gl: %s\n", fk_error(flares)), 1;

        // The application's tone map into its display target, shown in the window if any.
        glBindFramebuffer(GL_FRAMEBUFFER, ldrTarget);
        glUseProgram(tonemapProgram);
        glBindTextureUnit(0, hdr);
        glBindVertexArray(empty);
        glDrawArrays(GL_TRIANGLES, 0, 3);
#if EMBED_HAS_GLFW
        if (window) {
            int fw = 0, fh = 0;
            glfwGetFramebufferSize(window, &fw, &fh);
            glBlitNamedFramebuffer(ldrTarget, 0, 0, 0, w, h, 0, 0, fw, fh, GL_COLOR_BUFFER_BIT,
                                   GL_LINEAR);
            glfwSwapBuffers(window);
            glfwPollEvents();
        }
#endif
    }

    std::vector<float> coverage(lights.size());
    const int n = fk_engine_read_coverage(flares, coverage.data(), int(coverage.size()));
    int seen = 0;
    for (int i = 0; i < n; ++i) seen += coverage[std::size_t(i)] > 0.5f ? 1 : 0;
    std::printf("embed-gl: %zu lights (the sun and %zu lamps), %d more than half visible\n",
                lights.size(), city.lamps.size(), seen);
    {
        std::vector<unsigned char> rgba(std::size_t(w) * h * 4);
        glGetTextureImage(ldr, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        FILE* out = std::fopen(o.out.c_str(), "wb");
        if (!out) return std::fprintf(stderr, "embed-gl: cannot write %s\n", o.out.c_str()), 1;
        std::fprintf(out, "P6\n%d %d\n255\n", w, h);
        for (int y = h - 1; y >= 0; --y)  // GL rows are bottom-up
            for (int x = 0; x < w; ++x) std::fwrite(&rgba[(std::size_t(y) * w + x) * 4], 1, 3, out);
        std::fclose(out);
    }
    if (!o.sceneJson.empty()) {
        view.target = city.target;
        if (!writeSceneJson(view, w, h, o.sceneJson)) return 1;
    }
    if (!o.coverageJson.empty()) {
        FILE* c = std::fopen(o.coverageJson.c_str(), "w");
        if (!c) return 1;
        std::fprintf(c, "{\"coverage\": [");
        for (int i = 0; i < n; ++i)
            std::fprintf(c, "%s%.6f", i ? ", " : "", coverage[std::size_t(i)]);
        std::fprintf(c, "]}\n");
        std::fclose(c);
    }
    fk_engine_destroy(flares);
    return 0;
}
