// SPDX-License-Identifier: Apache-2.0
// The GL scene pass: sky and sun first (full-screen, no depth), then every opaque object in
// one draw with depth testing, then the translucent ones (opacity < 1) blended over without
// writing depth, and multiplied into a transmittance target for the occlusion passes. Programs,
// targets and the mesh live as long as the SceneRenderer, so a frame of an animation costs only its
// draw. Read back bottom-up and flipped to flarekit's top-row-first order.
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flarekit/Color.h"
#include "flarekit/gl/Render.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "scene/CameraMath.h"
#include "scene/MeshDraw.h"
#include "scene/SceneMesh.h"
#include "scene/SceneTargets.h"

namespace flarekit {

namespace {

//! Linear sky colours: a pale horizon under a deeper blue zenith (no seed prescribes them;
//! chosen so the sun at 50 stands far above the sky, as in the seeds' scenes).
constexpr float kHorizon[3] = {0.6f, 0.7f, 0.85f};
constexpr float kZenith[3] = {0.12f, 0.25f, 0.6f};
//! Ambient light on objects: a quarter of the average sky.
constexpr float kAmbientShare = 0.25f;
//! Shadow map side: 2048 texels over 160 m is 8 cm a texel, finer than the demo's leaves.
constexpr int kShadowMapSize = 2048;
//! The sun's camera sits this far back along the sun direction so casters up to there (tall
//! buildings beyond the shadowed region) still land in the map.
constexpr double kShadowEyeDistance = 1000;

gl::Texture makeMultisample(GLenum format, int samples, int w, int h) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &name);
    glTextureStorage2DMultisample(name, samples, format, w, h, GL_TRUE);
    return gl::Texture(name);
}

}  // namespace

struct SceneRenderer::Impl {
    int width = 0, height = 0, samples = 1;
    gl::Texture color, depth;      // single-sample results
    gl::Framebuffer target;        // color + depth
    gl::Texture msColor, msDepth;  // MSAA only
    gl::Framebuffer msTarget;      // MSAA only
    bool shadows = true;
    double shadowRange = 160;
    gl::Texture shadowMap;
    gl::Framebuffer shadowTarget;
    gl::Program sky, objects, shadowPass;
    gl::VertexArray vao;
    gl::Buffer vertices;
    GLsizei vertexCount = 0;
    gl::VertexArray translucentVao;
    gl::Buffer translucentVertices;
    std::vector<TranslucentRange> translucent;
    gl::Texture transmittance;
    gl::Framebuffer transmittanceTarget;
    gl::Program transmittancePass;

    void drawTranslucent(GLuint program) const;

    std::array<float, 16> drawShadowMap(const Scene& scene);
};

SceneRenderer::SceneRenderer(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
SceneRenderer::~SceneRenderer() = default;
SceneRenderer::SceneRenderer(SceneRenderer&&) noexcept = default;
SceneRenderer& SceneRenderer::operator=(SceneRenderer&&) noexcept = default;

int SceneRenderer::width() const {
    return m->width;
}
int SceneRenderer::height() const {
    return m->height;
}
int SceneRenderer::msaaSamples() const {
    return m->samples;
}

SceneTargets sceneTargets(const SceneRenderer& r) {
    const SceneRenderer::Impl& m = *r.m;
    return {m.color.get(),
            m.depth.get(),
            m.target.get(),
            m.msDepth.get(),
            m.vao.get(),
            m.samples,
            m.translucent.empty() ? 0u : m.transmittance.get()};
}

Result<SceneRenderer> SceneRenderer::create(const Scene& scene, const RenderOptions& options) {
    if (Status s = validateScene(scene); !s) return invalidInput("scene: " + s.error().message);
    if (Status s = gl::requireCurrentContext("SceneRenderer::create"); !s) return s.error();
    const int samples = options.msaaSamples;
    if (samples != 1 && samples != 2 && samples != 4 && samples != 8) {
        return invalidInput("msaa: expected 1, 2, 4 or 8 samples, got " + std::to_string(samples));
    }
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    if (samples > maxSamples) {
        return invalidInput("msaa: " + std::to_string(samples) +
                            " samples requested, the GL supports " + std::to_string(maxSamples));
    }
    auto impl = std::make_unique<Impl>();
    impl->width = scene.width;
    impl->height = scene.height;
    impl->samples = samples;
    if (!(options.shadowRange > 0 && options.shadowRange < 1e6)) {
        return invalidInput("shadow range: expected a positive number of metres below 1e6, got " +
                            std::to_string(options.shadowRange));
    }
    impl->shadows = options.shadows;
    impl->shadowRange = options.shadowRange;
    if (options.shadows) {
        impl->shadowMap = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, kShadowMapSize, kShadowMapSize);
        glTextureParameteri(impl->shadowMap.get(), GL_TEXTURE_COMPARE_MODE,
                            GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(impl->shadowMap.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        GLuint fb = 0;
        glCreateFramebuffers(1, &fb);
        impl->shadowTarget = gl::Framebuffer(fb);
        glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, impl->shadowMap.get(), 0);
        glNamedFramebufferDrawBuffer(fb, GL_NONE);
        glNamedFramebufferReadBuffer(fb, GL_NONE);
        if (glCheckNamedFramebufferStatus(fb, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            return internalError("OpenGL: shadow-map framebuffer incomplete");
        }
        auto shadowPass =
            gl::linkProgram({{GL_VERTEX_SHADER, "scene.vert", shaders::scene_vert},
                             {GL_FRAGMENT_SHADER, "shadow.frag", shaders::shadow_frag}});
        if (!shadowPass) return shadowPass.error();
        impl->shadowPass = std::move(*shadowPass);
    }
    impl->color = gl::makeTexture2D(GL_RGBA16F, scene.width, scene.height);
    impl->depth = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, scene.width, scene.height);
    auto target = gl::makeFramebuffer(impl->color.get(), impl->depth.get());
    if (!target) return target.error();
    impl->target = std::move(*target);
    if (samples > 1) {
        impl->msColor = makeMultisample(GL_RGBA16F, samples, scene.width, scene.height);
        impl->msDepth = makeMultisample(GL_DEPTH_COMPONENT32F, samples, scene.width, scene.height);
        auto ms = gl::makeFramebuffer(impl->msColor.get(), impl->msDepth.get());
        if (!ms) return ms.error();
        impl->msTarget = std::move(*ms);
    }
    auto sky = gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                                {GL_FRAGMENT_SHADER, "sky.frag", shaders::sky_frag}});
    if (!sky) return sky.error();
    impl->sky = std::move(*sky);
    auto objects = gl::linkProgram({{GL_VERTEX_SHADER, "scene.vert", shaders::scene_vert},
                                    {GL_FRAGMENT_SHADER, "scene.frag", shaders::scene_frag}});
    if (!objects) return objects.error();
    impl->objects = std::move(*objects);
    auto transmittancePass =
        gl::linkProgram({{GL_VERTEX_SHADER, "scene.vert", shaders::scene_vert},
                         {GL_FRAGMENT_SHADER, "transmittance.frag", shaders::transmittance_frag}});
    if (!transmittancePass) return transmittancePass.error();
    impl->transmittancePass = std::move(*transmittancePass);
    impl->transmittance = gl::makeTexture2D(GL_R16F, scene.width, scene.height);
    auto transmittanceTarget = gl::makeFramebuffer(impl->transmittance.get(), impl->depth.get());
    if (!transmittanceTarget) return transmittanceTarget.error();
    impl->transmittanceTarget = std::move(*transmittanceTarget);
    impl->vao = gl::makeVertexArray();
    impl->translucentVao = gl::makeVertexArray();
    SceneRenderer renderer(std::move(impl));
    if (Status s = renderer.setGeometry(scene); !s) return s.error();
    return renderer;
}

void SceneRenderer::Impl::drawTranslucent(GLuint program) const {
    glBindVertexArray(translucentVao.get());
    glUseProgram(program);
    const GLint opacityAt = gl::uniformLocation(program, "opacity");
    flarekit::drawTranslucent(
        translucent, [&](float opacity) { glProgramUniform1f(program, opacityAt, opacity); });
}

Status SceneRenderer::setGeometry(const Scene& scene) {
    if (scene.width != m->width || scene.height != m->height) {
        return invalidInput("scene renderer: geometry for a " + std::to_string(scene.width) + "x" +
                            std::to_string(scene.height) + " scene given to a " +
                            std::to_string(m->width) + "x" + std::to_string(m->height) +
                            " renderer");
    }
    // Opaque objects (and the ground) in one mesh, translucent ones in another.
    const Scene opaque = opaqueObjects(scene), clear = translucentObjects(scene);
    m->vertexCount = 0;
    if (Status s = uploadMesh(buildSceneMesh(opaque), m->vao.get(), m->vertices, m->vertexCount);
        !s)
        return s;
    GLsizei translucentCount = 0;
    if (Status s = uploadMesh(buildSceneMesh(clear), m->translucentVao.get(),
                              m->translucentVertices, translucentCount);
        !s)
        return s;
    m->translucent = translucentRanges(clear);
    return gl::checkError("mesh upload");
}

//! Renders the objects' depth as seen from the sun into the shadow map and returns the matrix
//! from world space to shadow-map coordinates in [0, 1]^3. The map covers a square of side
//! 2 x range centred `range` x 0.6 ahead of the camera on the ground plane of its view.
std::array<float, 16> SceneRenderer::Impl::drawShadowMap(const Scene& scene) {
    Impl& m = *this;
    const CameraBasis view = cameraBasis(scene.camera);
    Vec3 ahead = view.forward;
    ahead.y = 0;
    ahead = length(ahead) > 1e-6 ? normalize(ahead) : Vec3{0, 0, -1};
    const Vec3 focus = scene.camera.position + ahead * (0.6 * m.shadowRange);
    SceneCamera sunCamera;
    sunCamera.position = focus + scene.sun.direction * kShadowEyeDistance;
    sunCamera.lookAt = focus;
    sunCamera.up = std::abs(scene.sun.direction.y) < 0.99 ? Vec3{0, 1, 0} : Vec3{0, 0, -1};
    const Mat4 sunViewProjection =
        multiply(orthographicMatrix(m.shadowRange, m.shadowRange, 0.0, 2 * kShadowEyeDistance),
                 lookAtMatrix(sunCamera));
    const GLuint p = m.shadowPass.get();
    const auto vp = toFloat(sunViewProjection);
    glProgramUniformMatrix4fv(p, gl::uniformLocation(p, "viewProjection"), 1, GL_FALSE, vp.data());
    glBindFramebuffer(GL_FRAMEBUFFER, m.shadowTarget.get());
    glViewport(0, 0, kShadowMapSize, kShadowMapSize);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Slope-scaled offset against acne on surfaces the low sun grazes.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    glDisable(GL_CULL_FACE);
    glUseProgram(p);
    glBindVertexArray(m.vao.get());
    glDrawArrays(GL_TRIANGLES, 0, m.vertexCount);
    glDisable(GL_POLYGON_OFFSET_FILL);
    // NDC [-1, 1] -> [0, 1] on all three axes.
    Mat4 bias{};
    bias[0] = bias[5] = bias[10] = 0.5;
    bias[12] = bias[13] = bias[14] = 0.5;
    bias[15] = 1;
    return toFloat(multiply(bias, sunViewProjection));
}

Status SceneRenderer::draw(const Scene& scene) {
    const int w = m->width, h = m->height;
    const Mat4 viewProjection =
        multiply(perspectiveMatrix(scene.camera, double(w) / h), lookAtMatrix(scene.camera));
    const auto vp = toFloat(viewProjection), inv = toFloat(inverse(viewProjection));
    const Vec3 sunRadiance = scene.sun.color * scene.sun.intensity;
    // What lights a surface facing the sun: radiance x the disc's solid angle, pi sin^2(r).
    const double sinRadius = std::sin(scene.sun.angularRadiusDeg * std::numbers::pi / 180.0);
    const Vec3 sunIrradiance = sunRadiance * (std::numbers::pi * sinRadius * sinRadius);

    glBindFramebuffer(GL_FRAMEBUFFER, m->samples > 1 ? m->msTarget.get() : m->target.get());
    glViewport(0, 0, w, h);
    // glClear obeys the write masks, and the previous frame may have left depth writes off (a
    // scene without objects ends after the sky pass): set them before clearing.
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);

    const GLuint s = m->sky.get();
    glProgramUniformMatrix4fv(s, gl::uniformLocation(s, "inverseViewProjection"), 1, GL_FALSE,
                              inv.data());
    glProgramUniform2f(s, gl::uniformLocation(s, "viewportSize"), float(w), float(h));
    gl::setUniform(s, "sunDirection", scene.sun.direction);
    gl::setUniform(s, "sunRadiance", sunRadiance);
    glProgramUniform1f(s, gl::uniformLocation(s, "cosSunRadius"),
                       float(std::cos(scene.sun.angularRadiusDeg * std::numbers::pi / 180.0)));
    glProgramUniform3fv(s, gl::uniformLocation(s, "horizonColor"), 1, kHorizon);
    glProgramUniform3fv(s, gl::uniformLocation(s, "zenithColor"), 1, kZenith);
    glBindVertexArray(m->vao.get());
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(s);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    if (m->vertexCount > 0 || !m->translucent.empty()) {
        const GLuint o = m->objects.get();
        glProgramUniform1i(o, gl::uniformLocation(o, "shadowsEnabled"), m->shadows ? 1 : 0);
        if (m->shadows) {
            const auto shadow = m->drawShadowMap(scene);
            glProgramUniformMatrix4fv(o, gl::uniformLocation(o, "shadowMatrix"), 1, GL_FALSE,
                                      shadow.data());
            glProgramUniform1f(o, gl::uniformLocation(o, "shadowTexel"),
                               float(2 * m->shadowRange / kShadowMapSize));
            glProgramUniform1i(o, gl::uniformLocation(o, "sunShadow"), 0);
            glBindTextureUnit(0, m->shadowMap.get());
            glBindFramebuffer(GL_FRAMEBUFFER, m->samples > 1 ? m->msTarget.get() : m->target.get());
            glViewport(0, 0, w, h);
            glBindVertexArray(m->vao.get());
        }
        glProgramUniformMatrix4fv(o, gl::uniformLocation(o, "viewProjection"), 1, GL_FALSE,
                                  vp.data());
        gl::setUniform(o, "sunDirection", scene.sun.direction);
        gl::setUniform(o, "cameraPosition", scene.camera.position);
        gl::setUniform(o, "sunIrradiance", sunIrradiance);
        const float ambient[3] = {kAmbientShare * 0.5f * (kHorizon[0] + kZenith[0]),
                                  kAmbientShare * 0.5f * (kHorizon[1] + kZenith[1]),
                                  kAmbientShare * 0.5f * (kHorizon[2] + kZenith[2])};
        glProgramUniform3fv(o, gl::uniformLocation(o, "ambient"), 1, ambient);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);  // triangles are double-sided
        glProgramUniform1f(o, gl::uniformLocation(o, "opacity"), 1.f);
        glUseProgram(o);
        if (m->vertexCount > 0) glDrawArrays(GL_TRIANGLES, 0, m->vertexCount);
    }
    if (!m->translucent.empty()) {  // over the opaque objects, behind nothing it cannot see
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        m->drawTranslucent(m->objects.get());
        glDisable(GL_BLEND);
    }
    if (m->samples > 1) {
        // Resolve: colour averages the samples; depth blits must use NEAREST (one sample).
        glBlitNamedFramebuffer(m->msTarget.get(), m->target.get(), 0, 0, w, h, 0, 0, w, h,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBlitNamedFramebuffer(m->msTarget.get(), m->target.get(), 0, 0, w, h, 0, 0, w, h,
                               GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    if (!m->translucent.empty()) {
        glBindFramebuffer(GL_FRAMEBUFFER, m->transmittanceTarget.get());
        const float one[4] = {1.f, 1.f, 1.f, 1.f};
        glClearNamedFramebufferfv(m->transmittanceTarget.get(), GL_COLOR, 0, one);
        const GLuint t = m->transmittancePass.get();
        glProgramUniformMatrix4fv(t, gl::uniformLocation(t, "viewProjection"), 1, GL_FALSE,
                                  vp.data());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // destination x (1 - opacity)
        m->drawTranslucent(t);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return gl::checkError("scene render");
}

Result<Image> SceneRenderer::readColor() const {
    return gl::readTextureRgba(m->color.get(), m->width, m->height);
}

Result<Image> renderScene(const Scene& scene, const RenderOptions& options) {
    auto renderer = SceneRenderer::create(scene, options);
    if (!renderer) return renderer.error();
    if (Status s = renderer->draw(scene); !s) return s.error();
    return renderer->readColor();
}

}  // namespace flarekit
