// The engine: one compute dispatch per view measures every light (light_coverage.comp) and
// one instanced draw per preset element adds every light's flare (light_flare.vert). The
// CPU's share of a call is checking its arguments, copying the lights into a buffer and
// setting uniforms: it does not grow with what the GPU does per light.
#include "engine/Engine.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/EngineInput.h"
#include "engine/GlStateGuard.h"
#include "flare/ElementSprites.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"

namespace flarekit::engine {

namespace {

//! Light buffers written in turn, so a call's upload does not wait for the GPU to finish
//! reading the previous frame's lights (three: a frame being drawn, one queued, one filled).
constexpr int kLightRing = 3;
constexpr GLsizeiptr kLightBytes = 16 * sizeof(float);

void deleteSampler(GLuint n) {
    glDeleteSamplers(1, &n);
}
using Sampler = gl::Name<deleteSampler>;

Sampler makeSampler(GLenum filter) {
    GLuint s = 0;
    glCreateSamplers(1, &s);
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GLint(filter));
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GLint(filter));
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // A shadow-map depth texture (compare mode on) reads as 0/1 through texelFetch otherwise.
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return Sampler(s);
}

gl::Buffer makeBuffer(GLsizeiptr bytes) {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    return gl::Buffer(b);
}

//! The shader after the light_view.glsl prelude (and, for the occlusion passes, the per-light
//! state of light_state.glsl).
std::string withPrelude(const char* text, const std::string& defines, bool state = false) {
    std::string body(text);
    if (body.rfind("#version", 0) == 0) body = body.substr(body.find('\n') + 1);
    return "#version 450 core\n" + defines + shaders::light_view_glsl +
           (state ? shaders::light_state_glsl : "") + "\n#line 2\n" + body;
}

//! The uniforms both occlusion passes take from light_view.glsl and light_state.glsl.
struct LightPassUniforms {
    GLint view = -1, projection = -1, viewport = -1, convention = -1, viewIndex = -1,
          stateBase = -1, attack = -1, release = -1, guardBand = -1;

    void locate(GLuint n) {
        view = gl::uniformLocation(n, "viewMatrix");
        projection = gl::uniformLocation(n, "projectionMatrix");
        viewport = gl::uniformLocation(n, "viewport");
        convention = gl::uniformLocation(n, "depthConvention");
        viewIndex = gl::uniformLocation(n, "viewIndex");
        stateBase = gl::uniformLocation(n, "stateBase");
        attack = gl::uniformLocation(n, "attackStep");
        release = gl::uniformLocation(n, "releaseStep");
        guardBand = gl::uniformLocation(n, "depthPastViewport");
    }
    //! View `index` of a frame: its matrices, viewport and convention, its rows of the state,
    //! the filter's steps for its dt, and whether depth past its viewport may be read.
    void set(GLuint p, const fk_frame& f, int index, int maxLights, const TemporalParams& t,
             bool pastViewport) const {
        glProgramUniformMatrix4fv(p, view, 1, GL_FALSE, f.view);
        glProgramUniformMatrix4fv(p, projection, 1, GL_FALSE, f.projection);
        glProgramUniform4iv(p, viewport, 1, f.viewport);
        glProgramUniform1i(p, convention, int(f.depth_convention));
        glProgramUniform1i(p, viewIndex, index);
        glProgramUniform1i(p, stateBase, index * maxLights);
        glProgramUniform1f(p, attack, float(smoothingStep(f.dt_seconds, t.attackSeconds)));
        glProgramUniform1f(p, release, float(smoothingStep(f.dt_seconds, t.releaseSeconds)));
        glProgramUniform1i(p, guardBand, pastViewport ? 1 : 0);
    }
};

struct CoverageProgram {
    gl::Program program;
    LightPassUniforms pass;
    GLint perSide = -1, hasTransmittance = -1, textureSize = -1, sampleCount = -1,
          samplePositions = -1, depthSamples = -1;
};

Result<CoverageProgram> linkCoverage(bool multisample) {
    auto p = gl::linkProgram({{GL_COMPUTE_SHADER, "light_coverage.comp",
                               withPrelude(shaders::light_coverage_comp,
                                           multisample ? "#define MULTISAMPLE\n" : "", true)}});
    if (!p) return p.error();
    CoverageProgram c;
    c.program = std::move(*p);
    const GLuint n = c.program.get();
    c.pass.locate(n);
    c.perSide = gl::uniformLocation(n, "perSide");
    c.depthSamples = gl::uniformLocation(n, "samplesPerPixel");
    c.hasTransmittance = gl::uniformLocation(n, "hasTransmittance");
    c.textureSize = gl::uniformLocation(n, "depthTextureSize");
    if (multisample) {
        c.sampleCount = gl::uniformLocation(n, "sampleCount");
        c.samplePositions = gl::uniformLocation(n, "samplePositions");
    }
    return c;
}

//! The texture-mask reduction (sunmap_coverage.comp) and its uniforms.
struct SunMapProgram {
    gl::Program program;
    LightPassUniforms pass;
    GLint tileSize = -1, tilesPerRow = -1;
};

Result<SunMapProgram> linkSunMap() {
    auto p = gl::linkProgram({{GL_COMPUTE_SHADER, "sunmap_coverage.comp",
                               withPrelude(shaders::sunmap_coverage_comp, "", true)}});
    if (!p) return p.error();
    SunMapProgram c;
    c.program = std::move(*p);
    const GLuint n = c.program.get();
    c.pass.locate(n);
    c.tileSize = gl::uniformLocation(n, "tileSize");
    c.tilesPerRow = gl::uniformLocation(n, "tilesPerRow");
    return c;
}

//! Sun-map tiles: 64 texels a side (about 3,200 inside the cone's circle: an edge across it is
//! placed to half a texel, under 0.01 of the disc) while the atlas stays within 4096^2; for
//! more than 4,096 lights they shrink to fit.
constexpr int kMaxTileSize = 64, kMaxAtlasSide = 4096;
//! The widest cone a tile holds: 80 degrees half-angle (tan = 5.7); a camera nearer a sphere
//! light than that is as good as inside it.
constexpr double kMaxSunMapHalfAngle = 1.4;

//! Column-major view-projection of the camera at `eye` looking along unit `axis` whose field of
//! view is the cone of half-angle `half`, to distance `farPlane`, in the clip space of the
//! frame's depth convention (so the application's clip control draws it unchanged).
std::array<float, 16> sunMapCamera(const double eye[3], const double axis[3], double half,
                                   double nearPlane, double farPlane,
                                   fk_depth_convention convention) {
    const double up[3] = {std::abs(axis[1]) < 0.99 ? 0.0 : 1.0,
                          std::abs(axis[1]) < 0.99 ? 1.0 : 0.0, 0.0};
    double side[3] = {axis[1] * up[2] - axis[2] * up[1], axis[2] * up[0] - axis[0] * up[2],
                      axis[0] * up[1] - axis[1] * up[0]};
    const double sl = std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
    for (double& c : side) c /= sl;
    const double u[3] = {side[1] * axis[2] - side[2] * axis[1],
                         side[2] * axis[0] - side[0] * axis[2],
                         side[0] * axis[1] - side[1] * axis[0]};
    const auto dot = [](const double* a, const double* b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const double view[16] = {
        side[0], u[0], -axis[0], 0, side[1],         u[1],         -axis[1],       0,
        side[2], u[2], -axis[2], 0, -dot(side, eye), -dot(u, eye), dot(axis, eye), 1};
    const double f = 1.0 / std::tan(std::min(half, kMaxSunMapHalfAngle));
    const double n = std::min(nearPlane, 0.5 * farPlane), far = farPlane;
    double proj[16] = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0};
    if (convention == FK_DEPTH_MINUS_ONE_TO_ONE) {
        proj[10] = (far + n) / (n - far);
        proj[14] = 2 * far * n / (n - far);
    } else {
        proj[10] = far / (n - far);
        proj[14] = far * n / (n - far);
    }
    std::array<float, 16> vp{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += proj[k * 4 + r] * view[c * 4 + k];
            vp[std::size_t(c * 4 + r)] = float(sum);
        }
    return vp;
}

//! The frame's own near plane, read back from its projection under its convention: the sun
//! maps clip there too. (A plane much nearer than the scene's scale makes float clipping of
//! large triangles, a ground plane, scatter slivers over the tiny field of view of a sun map.)
double nearPlaneOf(const fk_frame& f) {
    const double p10 = f.projection[10], p14 = f.projection[14];
    double n = 0.1;
    if (f.depth_convention == FK_DEPTH_MINUS_ONE_TO_ONE && p10 != 1.0)
        n = p14 / (p10 - 1.0);
    else if (f.depth_convention == FK_DEPTH_ZERO_TO_ONE && p10 != 0.0)
        n = p14 / p10;
    else if (f.depth_convention == FK_DEPTH_REVERSED_Z && p10 != -1.0)
        n = p14 / (p10 + 1.0);
    return std::isfinite(n) && n > 1e-6 ? n : 0.1;
}

struct FlareProgram {
    gl::Program program;
    GLint view = -1, projection = -1, viewport = -1, convention = -1, viewIndex = -1, presetId = -1,
          t = -1, halfSize = -1, guardBand = -1, referenceFlux = -1, edgeStreak = -1, reach = -1;
};

Result<FlareProgram> linkFlare() {
    auto p = gl::linkProgram(
        {{GL_VERTEX_SHADER, "light_flare.vert", withPrelude(shaders::light_flare_vert, "")},
         {GL_FRAGMENT_SHADER, "light_flare.frag", shaders::light_flare_frag}});
    if (!p) return p.error();
    FlareProgram f;
    f.program = std::move(*p);
    const GLuint n = f.program.get();
    f.view = gl::uniformLocation(n, "viewMatrix");
    f.projection = gl::uniformLocation(n, "projectionMatrix");
    f.viewport = gl::uniformLocation(n, "viewport");
    f.convention = gl::uniformLocation(n, "depthConvention");
    f.viewIndex = gl::uniformLocation(n, "viewIndex");
    f.presetId = gl::uniformLocation(n, "presetId");
    f.t = gl::uniformLocation(n, "t");
    f.halfSize = gl::uniformLocation(n, "halfSize");
    f.guardBand = gl::uniformLocation(n, "guardBand");
    f.referenceFlux = gl::uniformLocation(n, "referenceFlux");
    f.edgeStreak = gl::uniformLocation(n, "edgeStreak");
    f.reach = gl::uniformLocation(n, "reach");
    return f;
}

struct LoadedPreset {
    Preset preset;
    int spriteHeight = 0;  //!< frame height the sprites were made for (0: none yet)
    std::vector<ElementSprite> sprites;
};

//! Where the samples of an n-sample pixel sit (glGetMultisamplefv), per sample count.
struct SamplePattern {
    int samples = 0;
    std::array<float, 32> positions{};
};

}  // namespace

struct Engine::Impl {
    int maxLights = 0;
    CoverageProgram coverage[2];  //!< single-sample depth, multisampled depth
    SunMapProgram sunMap;
    bool textureMask = false;  //!< the method: texture-mask (sun maps) instead of compute
    fk_occluder_callback occluders = nullptr;
    void* occludersUser = nullptr;
    gl::Texture atlas;  //!< RGBA8 sun maps, one tile per light (made with the method)
    gl::Framebuffer atlasTarget;
    int tileSize = 0, tilesPerRow = 0;
    FlareProgram flare;
    std::array<gl::Buffer, kLightRing> lightBuffers;
    int ringAt = 0;
    gl::Buffer state;           //!< vec4 per light and view (light_coverage.comp)
    gl::Texture coverageImage;  //!< R32F, maxLights x FK_MAX_VIEWS: filtered coverage
    gl::VertexArray vertexArray;
    gl::Framebuffer probe;  //!< for asking where a multisampled texture's samples are
    Sampler nearest, linear;
    std::vector<LoadedPreset> presets;
    std::vector<SamplePattern> patterns;
    std::array<GLuint, FK_MAX_VIEWS> transmittance{};
    std::array<bool, FK_MAX_VIEWS> guardBand{};
    int samplesPerSide = kDefaultSamplesPerSide;
    TemporalParams temporal;
    int lastViews = 0;
    std::array<int, FK_MAX_VIEWS> lastCount{};
    std::vector<float> packed;  //!< the lights as uploaded, kept to reuse its memory

    GLuint uploadLights(const fk_light* lights, int count);
    const SamplePattern& patternFor(GLuint texture, int samples);
    Status ensureSprites(LoadedPreset& p, int height);
    Status measureSunMaps(int view, const fk_frame& f, const fk_light* lights, int count,
                          GLuint lightBuffer);
};

Status Engine::Impl::measureSunMaps(int view, const fk_frame& f, const fk_light* lights, int count,
                                    GLuint lightBuffer) {
    // The eye: view = [R | t] is rigid, so the eye is -R^T t.
    double eye[3];
    for (int i = 0; i < 3; ++i)
        eye[i] = -(double(f.view[i * 4 + 0]) * f.view[12] + double(f.view[i * 4 + 1]) * f.view[13] +
                   double(f.view[i * 4 + 2]) * f.view[14]);
    const float white[4] = {1, 1, 1, 1};
    glClearNamedFramebufferfv(atlasTarget.get(), GL_COLOR, 0, white);
    const double nearPlane = nearPlaneOf(f);
    for (int i = 0; i < count; ++i) {
        const fk_light& l = lights[i];
        double axis[3], half = 0, farPlane = 1e7;
        if (l.type == FK_LIGHT_POINT) {
            double d[3] = {l.position[0] - eye[0], l.position[1] - eye[1], l.position[2] - eye[2]};
            const double dist = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (dist <= l.radius) continue;  // inside the light: the reduction says 1
            for (int k = 0; k < 3; ++k) axis[k] = d[k] / dist;
            half = std::asin(double(l.radius) / dist);
            // Only what lies before the light hides it (kNearSide of light_view.glsl).
            farPlane = (dist - l.radius) * 0.999;
        } else {
            const double dl = std::sqrt(double(l.direction[0]) * l.direction[0] +
                                        double(l.direction[1]) * l.direction[1] +
                                        double(l.direction[2]) * l.direction[2]);
            for (int k = 0; k < 3; ++k) axis[k] = l.direction[k] / dl;
            half = double(l.radius) * 3.14159265358979323846 / 180.0;
        }
        const std::array<float, 16> vp =
            sunMapCamera(eye, axis, half, nearPlane, farPlane, f.depth_convention);
        const int tile[4] = {(i % tilesPerRow) * tileSize, (i / tilesPerRow) * tileSize, tileSize,
                             tileSize};
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, atlasTarget.get());
        glViewport(tile[0], tile[1], tile[2], tile[3]);
        occluders(occludersUser, view, i, vp.data(), atlasTarget.get(), tile);
    }
    // The callbacks may have bound anything: bind what the reduction reads now.
    const SunMapProgram& c = sunMap;
    const GLuint p = c.program.get();
    c.pass.set(p, f, view, maxLights, temporal, false);
    glProgramUniform1i(p, c.tileSize, tileSize);
    glProgramUniform1i(p, c.tilesPerRow, tilesPerRow);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStateBinding, state.get());
    glBindImageTexture(kStateImageUnit, coverageImage.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    // The sun maps were drawn: make the draws visible to the fetches (rendering then sampling
    // needs no barrier, but a compute read after a draw on the same texture is ordered anyway).
    glBindTextureUnit(kDepthUnit, atlas.get());
    glBindSampler(kDepthUnit, nearest.get());
    glUseProgram(p);
    glDispatchCompute(GLuint(count), 1, 1);
    return Ok{};
}

GLuint Engine::Impl::uploadLights(const fk_light* lights, int count) {
    const GLuint buffer = lightBuffers[std::size_t(ringAt)].get();
    ringAt = (ringAt + 1) % kLightRing;
    if (count == 0) return buffer;
    packLights(lights, count, packed);
    glNamedBufferSubData(buffer, 0, GLsizeiptr(packed.size() * sizeof(float)), packed.data());
    return buffer;
}

const SamplePattern& Engine::Impl::patternFor(GLuint texture, int samples) {
    for (const SamplePattern& p : patterns)
        if (p.samples == samples) return p;
    SamplePattern p;
    p.samples = samples;
    glNamedFramebufferTexture(probe.get(), GL_DEPTH_ATTACHMENT, texture, 0);
    glNamedFramebufferDrawBuffer(probe.get(), GL_NONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, probe.get());  // the guard puts the caller's back
    for (int i = 0; i < samples; ++i)
        glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), &p.positions[std::size_t(2 * i)]);
    glNamedFramebufferTexture(probe.get(), GL_DEPTH_ATTACHMENT, 0, 0);
    patterns.push_back(p);
    return patterns.back();
}

Status Engine::Impl::ensureSprites(LoadedPreset& p, int height) {
    if (p.spriteHeight == height) return Ok{};
    auto sprites = buildElementSprites(p.preset, height);
    if (!sprites) return sprites.error();
    p.sprites = std::move(*sprites);
    p.spriteHeight = height;
    return Ok{};
}

Engine::Engine(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
Engine::~Engine() = default;

Result<std::unique_ptr<Engine>> Engine::create(int maxLights) {
    if (maxLights < 1 || maxLights > FK_MAX_LIGHTS) {
        return invalidInput("max_lights: expected 1.." + std::to_string(FK_MAX_LIGHTS) + ", got " +
                            std::to_string(maxLights));
    }
    if (!gl::hasCurrentContext()) {
        return invalidInput(
            "no OpenGL context is current on this thread (the application's GL "
            "4.5 core context must be current in every call)");
    }
    if (epoxy_gl_version() < 45) {
        return invalidInput("fk_engine_create: expected a current OpenGL 4.5 context, got " +
                            std::to_string(epoxy_gl_version() / 10) + "." +
                            std::to_string(epoxy_gl_version() % 10));
    }
    // Errors the application left pending would read as this call's own below; they are
    // cleared first (the one GL side effect of creating an engine, documented in flarekit.h).
    while (glGetError() != GL_NO_ERROR) {
    }
    const GlStateGuard guard;
    auto impl = std::make_unique<Impl>();
    impl->maxLights = maxLights;
    for (int ms = 0; ms < 2; ++ms) {
        auto c = linkCoverage(ms == 1);
        if (!c) return c.error();
        impl->coverage[ms] = std::move(*c);
    }
    auto sunMap = linkSunMap();
    if (!sunMap) return sunMap.error();
    impl->sunMap = std::move(*sunMap);
    auto flare = linkFlare();
    if (!flare) return flare.error();
    impl->flare = std::move(*flare);
    for (gl::Buffer& b : impl->lightBuffers) b = makeBuffer(GLsizeiptr(maxLights) * kLightBytes);
    impl->state = makeBuffer(GLsizeiptr(maxLights) * FK_MAX_VIEWS * 4 * GLsizeiptr(sizeof(float)));
    impl->coverageImage = gl::makeTexture2D(GL_R32F, maxLights, FK_MAX_VIEWS);
    glTextureParameteri(impl->coverageImage.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(impl->coverageImage.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    impl->vertexArray = gl::makeVertexArray();
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    impl->probe = gl::Framebuffer(fbo);
    impl->nearest = makeSampler(GL_NEAREST);
    impl->linear = makeSampler(GL_LINEAR);
    auto engine = std::unique_ptr<Engine>(new Engine(std::move(impl)));
    if (Status s = engine->reset(); !s) return s.error();
    if (Status s = gl::checkError("fk_engine_create"); !s) return s.error();
    return engine;
}

Status Engine::reset() {
    const float zero = 0.f;
    glClearNamedBufferData(m->state.get(), GL_R32F, GL_RED, GL_FLOAT, &zero);
    glClearTexImage(m->coverageImage.get(), 0, GL_RED, GL_FLOAT, &zero);
    m->lastViews = 0;
    m->lastCount.fill(0);
    return Ok{};
}

Result<int> Engine::loadPreset(const std::string& nameOrPath) {
    auto preset = flarekit::loadPreset(nameOrPath);
    if (!preset) return preset.error();
    LoadedPreset p;
    p.preset = std::move(*preset);
    m->presets.push_back(std::move(p));
    return int(m->presets.size()) - 1;
}

Status Engine::setMethod(const std::string& method) {
    if (method == "compute") {
        m->textureMask = false;
        return Ok{};
    }
    if (method != "texture-mask") {
        return invalidInput(
            "method: expected \"compute\" (depth, one batched pass) or "
            "\"texture-mask\" (sun maps the application's occluder callback "
            "draws), got \"" +
            method + "\"");
    }
    if (!m->atlas) {
        const GlStateGuard guard;
        m->tilesPerRow = int(std::ceil(std::sqrt(double(m->maxLights))));
        m->tileSize = std::min(kMaxTileSize, kMaxAtlasSide / m->tilesPerRow);
        const int side = m->tilesPerRow * m->tileSize;
        m->atlas = gl::makeTexture2D(GL_RGBA8, side, side);
        auto target = gl::makeFramebuffer(m->atlas.get());
        if (!target) return target.error();
        m->atlasTarget = std::move(*target);
    }
    m->textureMask = true;
    return Ok{};
}

Status Engine::setOccluderCallback(fk_occluder_callback callback, void* user) {
    m->occluders = callback;
    m->occludersUser = user;
    return Ok{};
}

Status Engine::setSamples(int perSide) {
    if (perSide < 1 || perSide > kMaxSamplesPerSide) {
        return invalidInput("samples_per_side: expected 1.." + std::to_string(kMaxSamplesPerSide) +
                            ", got " + std::to_string(perSide));
    }
    m->samplesPerSide = perSide;
    return Ok{};
}

Status Engine::setTemporal(float attackSeconds, float releaseSeconds, float guardBand) {
    TemporalParams t = m->temporal;
    t.attackSeconds = attackSeconds;
    t.releaseSeconds = releaseSeconds;
    t.guardBand = guardBand;
    if (Status s = validateTemporalParams(t); !s) return s;
    m->temporal = t;
    return Ok{};
}

Status Engine::setTransmittance(int view, unsigned texture) {
    if (view < 0 || view >= FK_MAX_VIEWS) {
        return invalidInput("view: expected 0.." + std::to_string(FK_MAX_VIEWS - 1) + ", got " +
                            std::to_string(view));
    }
    if (texture != 0) {
        GLint target = 0;
        if (glIsTexture(texture)) glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
        if (target != GL_TEXTURE_2D) {
            return invalidInput("texture: expected 0 or the name of a GL_TEXTURE_2D, got " +
                                std::to_string(texture));
        }
    }
    m->transmittance[std::size_t(view)] = texture;
    return Ok{};
}

Status Engine::setGuardBand(int view, bool enabled) {
    if (view < 0 || view >= FK_MAX_VIEWS) {
        return invalidInput("view: expected 0.." + std::to_string(FK_MAX_VIEWS - 1) + ", got " +
                            std::to_string(view));
    }
    m->guardBand[std::size_t(view)] = enabled;
    return Ok{};
}

unsigned Engine::coverageTexture() const {
    return m->coverageImage.get();
}

Status Engine::occlusion(std::span<const fk_frame> frames, const fk_light* lights, int count) {
    if (frames.empty() || frames.size() > FK_MAX_VIEWS) {
        return invalidInput("views: expected 1.." + std::to_string(FK_MAX_VIEWS) + ", got " +
                            std::to_string(frames.size()));
    }
    std::array<DepthTextureInfo, FK_MAX_VIEWS> depth{};
    for (std::size_t v = 0; v < frames.size(); ++v) {
        auto info = checkFrame(&frames[v], frames.size() > 1 ? "frames[" + std::to_string(v) + "]"
                                                             : std::string("frame"));
        if (!info) return info.error();
        depth[v] = *info;
    }
    if (Status s = checkLights(lights, count, m->maxLights, int(m->presets.size())); !s) return s;
    if (m->textureMask && !m->occluders) {
        return invalidInput(
            "method texture-mask: expected an occluder callback "
            "(fk_engine_set_occluder_callback) to draw the sun maps");
    }
    m->lastViews = int(frames.size());
    for (std::size_t v = 0; v < frames.size(); ++v) m->lastCount[v] = count;
    if (count == 0) return Ok{};

    const GlStateGuard guard;
    const GLuint lightBuffer = m->uploadLights(lights, count);
    if (m->textureMask) {
        for (std::size_t v = 0; v < frames.size(); ++v)
            if (Status s = m->measureSunMaps(int(v), frames[v], lights, count, lightBuffer); !s)
                return s;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                        GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        return Ok{};
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStateBinding, m->state.get());
    glBindImageTexture(kStateImageUnit, m->coverageImage.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    for (std::size_t v = 0; v < frames.size(); ++v) {
        const fk_frame& f = frames[v];
        const CoverageProgram& c = m->coverage[depth[v].multisample ? 1 : 0];
        const GLuint p = c.program.get();
        c.pass.set(p, f, int(v), m->maxLights, m->temporal, m->guardBand[v]);
        glProgramUniform1i(p, c.perSide, m->samplesPerSide);
        glProgramUniform1i(p, c.depthSamples, depth[v].samples);
        glProgramUniform2f(p, c.textureSize, float(f.width), float(f.height));
        const GLuint transmittance = m->transmittance[v];
        glProgramUniform1i(p, c.hasTransmittance, transmittance != 0 ? 1 : 0);
        glBindTextureUnit(kTransmittanceUnit, transmittance);
        glBindSampler(kTransmittanceUnit, m->linear.get());
        if (depth[v].multisample) {
            const SamplePattern& pattern = m->patternFor(f.depth_texture, depth[v].samples);
            glProgramUniform1i(p, c.sampleCount, depth[v].samples);
            glProgramUniform2fv(p, c.samplePositions, depth[v].samples, pattern.positions.data());
        }
        // A depth-stencil texture may be set to hand out stencil: read its depth, then put
        // the application's mode back.
        GLint mode = GL_DEPTH_COMPONENT;
        glGetTextureParameteriv(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
        if (mode != GL_DEPTH_COMPONENT)
            glTextureParameteri(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
        glBindTextureUnit(kDepthUnit, f.depth_texture);
        glBindSampler(kDepthUnit, m->nearest.get());
        glUseProgram(p);
        glDispatchCompute(GLuint(count), 1, 1);
        if (mode != GL_DEPTH_COMPONENT)
            glTextureParameteri(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, mode);
    }
    // The application's shaders (texelFetch of the coverage texture), the flare draw and
    // read-backs all see the stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return Ok{};
}

Status Engine::draw(int view, const fk_frame* frame, const fk_light* lights, int count,
                    unsigned framebuffer) {
    if (view < 0 || view >= FK_MAX_VIEWS) {
        return invalidInput("view: expected 0.." + std::to_string(FK_MAX_VIEWS - 1) + ", got " +
                            std::to_string(view));
    }
    if (!frame) return invalidInput("frame: expected a frame, got NULL");
    // Drawing needs the frame's matrices and viewport, not its depth texture.
    fk_frame numbers = *frame;
    if (auto info = checkFrame(&numbers, "frame"); !info) {
        if (info.error().message.find(".depth_texture") == std::string::npos) return info.error();
    }
    if (Status s = checkLights(lights, count, m->maxLights, int(m->presets.size())); !s) return s;
    if (Status s = checkFramebuffer(framebuffer); !s) return s;
    if (count == 0) return Ok{};

    const GlStateGuard guard;
    const int height = frame->viewport[3];
    std::vector<char> used(m->presets.size(), 0);
    for (int i = 0; i < count; ++i)
        if (lights[i].preset >= 0) used[std::size_t(lights[i].preset)] = 1;
    for (std::size_t p = 0; p < m->presets.size(); ++p) {
        if (!used[p]) continue;
        if (Status s = m->ensureSprites(m->presets[p], height); !s) return s;
    }
    const GLuint lightBuffer = m->uploadLights(lights, count);
    const FlareProgram& f = m->flare;
    const GLuint p = f.program.get();
    glProgramUniformMatrix4fv(p, f.view, 1, GL_FALSE, frame->view);
    glProgramUniformMatrix4fv(p, f.projection, 1, GL_FALSE, frame->projection);
    glProgramUniform4iv(p, f.viewport, 1, frame->viewport);
    glProgramUniform1i(p, f.convention, int(frame->depth_convention));
    glProgramUniform1i(p, f.viewIndex, view);
    glProgramUniform1f(p, f.guardBand, float(m->temporal.guardBand));
    glProgramUniform1f(p, f.referenceFlux, float(kReferenceFlux));

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(frame->viewport[0], frame->viewport[1], frame->viewport[2], frame->viewport[3]);
    setAdditiveDrawState();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindTextureUnit(kCoverageUnit, m->coverageImage.get());
    glBindSampler(kCoverageUnit, m->nearest.get());
    glBindSampler(kElementUnit, 0);  // the element textures' own filtering and border
    glBindVertexArray(m->vertexArray.get());
    glUseProgram(p);
    for (std::size_t id = 0; id < m->presets.size(); ++id) {
        if (!used[id]) continue;
        glProgramUniform1i(p, f.presetId, int(id));
        for (const ElementSprite& s : m->presets[id].sprites) {
            glProgramUniform1f(p, f.t, s.t);
            glProgramUniform2f(p, f.halfSize, s.halfW, s.halfH);
            glProgramUniform1i(p, f.edgeStreak, s.edgeStreak ? 1 : 0);
            glProgramUniform1f(p, f.reach, s.reach);
            glBindTextureUnit(kElementUnit, s.texture.get());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
        }
    }
    return Ok{};
}

Result<int> Engine::readView(int view, float* coverage, float* inFrame, float* filtered,
                             int count) {
    if (view < 0 || view >= FK_MAX_VIEWS) {
        return invalidInput("view: expected 0.." + std::to_string(FK_MAX_VIEWS - 1) + ", got " +
                            std::to_string(view));
    }
    if (count < 0) return invalidInput("count: expected >= 0, got " + std::to_string(count));
    if (count > 0 && !coverage && !inFrame && !filtered)
        return invalidInput("out: expected an array of count floats, got NULL");
    if (view >= m->lastViews) return 0;
    const int n = std::min(count, m->lastCount[std::size_t(view)]);
    if (n == 0) return 0;
    std::vector<float> state(std::size_t(n) * 4);
    glGetNamedBufferSubData(m->state.get(),
                            GLintptr(view) * m->maxLights * 4 * GLintptr(sizeof(float)),
                            GLsizeiptr(state.size() * sizeof(float)), state.data());
    for (int i = 0; i < n; ++i) {
        const float* s = state.data() + std::size_t(i) * 4;
        if (coverage) coverage[i] = s[0];
        if (filtered) filtered[i] = s[1];
        if (inFrame) inFrame[i] = s[2];
    }
    return n;
}

}  // namespace flarekit::engine
