// The GL scene pass: sky and sun first (full-screen, no depth), then every object in one
// draw with depth testing. Read back bottom-up and flipped to flarekit's top-row-first order.
#include <epoxy/gl.h>

#include <cmath>
#include <numbers>

#include "flarekit/Color.h"
#include "flarekit/Render.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "scene/CameraMath.h"
#include "scene/SceneMesh.h"

namespace flarekit {

namespace {

//! Linear sky colours: a pale horizon under a deeper blue zenith (no seed prescribes them;
//! chosen so the sun at 50 stands far above the sky, as in the seeds' scenes).
constexpr float kHorizon[3] = {0.6f, 0.7f, 0.85f};
constexpr float kZenith[3] = {0.12f, 0.25f, 0.6f};
//! Ambient light on objects: a quarter of the average sky.
constexpr float kAmbientShare = 0.25f;

void setVec3(GLuint program, const char* name, Vec3 v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), float(v.x), float(v.y), float(v.z));
}

}  // namespace

Result<Image> renderScene(const Scene& scene) {
    const int w = scene.width, h = scene.height;
    gl::Texture color = gl::makeTexture2D(GL_RGBA16F, w, h);
    gl::Texture depth = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, w, h);
    auto fb = gl::makeFramebuffer(color, &depth);
    if (!fb) return fb.error();
    auto sky = gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                                {GL_FRAGMENT_SHADER, "sky.frag", shaders::sky_frag}});
    if (!sky) return sky.error();
    auto objects = gl::linkProgram({{GL_VERTEX_SHADER, "scene.vert", shaders::scene_vert},
                                    {GL_FRAGMENT_SHADER, "scene.frag", shaders::scene_frag}});
    if (!objects) return objects.error();

    const Mat4 viewProjection = multiply(perspectiveMatrix(scene.camera, double(w) / h), lookAtMatrix(scene.camera));
    const auto vp = toFloat(viewProjection), inv = toFloat(inverse(viewProjection));
    const Vec3 sunRadiance = scene.sun.color * scene.sun.intensity;

    glBindFramebuffer(GL_FRAMEBUFFER, fb->get());
    glViewport(0, 0, w, h);
    // glClear obeys the write masks, and the previous call may have left depth writes off (a
    // scene without objects ends after the sky pass): set them before clearing.
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);

    const GLuint s = sky->get();
    glProgramUniformMatrix4fv(s, glGetUniformLocation(s, "inverseViewProjection"), 1, GL_FALSE, inv.data());
    glProgramUniform2f(s, glGetUniformLocation(s, "viewportSize"), float(w), float(h));
    setVec3(s, "sunDirection", scene.sun.direction);
    setVec3(s, "sunRadiance", sunRadiance);
    glProgramUniform1f(s, glGetUniformLocation(s, "cosSunRadius"),
                       float(std::cos(scene.sun.angularRadiusDeg * std::numbers::pi / 180.0)));
    glProgramUniform3fv(s, glGetUniformLocation(s, "horizonColor"), 1, kHorizon);
    glProgramUniform3fv(s, glGetUniformLocation(s, "zenithColor"), 1, kZenith);
    GLuint vaoName = 0;
    glCreateVertexArrays(1, &vaoName);
    gl::VertexArray vao(vaoName);
    glBindVertexArray(vaoName);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(s);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    const std::vector<MeshVertex> mesh = buildSceneMesh(scene);
    gl::Buffer vertices;
    if (!mesh.empty()) {
        GLuint buffer = 0;
        glCreateBuffers(1, &buffer);
        vertices = gl::Buffer(buffer);
        glNamedBufferStorage(buffer, GLsizeiptr(mesh.size() * sizeof(MeshVertex)), mesh.data(), 0);
        glVertexArrayVertexBuffer(vaoName, 0, buffer, 0, sizeof(MeshVertex));
        for (GLuint attr = 0; attr < 3; ++attr) {
            glEnableVertexArrayAttrib(vaoName, attr);
            glVertexArrayAttribFormat(vaoName, attr, 3, GL_FLOAT, GL_FALSE, attr * 3 * sizeof(float));
            glVertexArrayAttribBinding(vaoName, attr, 0);
        }
        const GLuint o = objects->get();
        glProgramUniformMatrix4fv(o, glGetUniformLocation(o, "viewProjection"), 1, GL_FALSE, vp.data());
        setVec3(o, "sunDirection", scene.sun.direction);
        setVec3(o, "sunRadiance", sunRadiance);
        const float ambient[3] = {kAmbientShare * 0.5f * (kHorizon[0] + kZenith[0]),
                                  kAmbientShare * 0.5f * (kHorizon[1] + kZenith[1]),
                                  kAmbientShare * 0.5f * (kHorizon[2] + kZenith[2])};
        glProgramUniform3fv(o, glGetUniformLocation(o, "ambient"), 1, ambient);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);  // triangles are double-sided
        glUseProgram(o);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(mesh.size()));
    }

    Image frame(w, h);
    std::vector<float> pixels(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
        return internalError("OpenGL: scene render failed (error 0x" + std::to_string(err) + ")");
    }
    for (int y = 0; y < h; ++y) {
        const float* src = pixels.data() + std::size_t(h - 1 - y) * std::size_t(w) * 4;
        std::copy(src, src + std::size_t(w) * 4, frame.row(y));
    }
    return frame;
}

FlaredFrame addSunFlare(Image& frame, const Scene& scene, const Preset& preset, double coverage) {
    FlaredFrame result;
    result.sunInFront = projectDirection(scene, scene.sun.direction, result.sunPixel);
    if (!result.sunInFront || coverage <= 0) return result;
    const Vec3 radiance = scene.sun.color * scene.sun.intensity;
    const float brightness = luminance(float(radiance.x), float(radiance.y), float(radiance.z));
    result.flareIntensity = float(coverage) * flareScaleForBrightness(brightness);
    renderFlare(frame, preset, result.sunPixel, result.flareIntensity);
    return result;
}

}  // namespace flarekit
