// SPDX-License-Identifier: Apache-2.0
// The engine: one compute dispatch per view measures every light (light_coverage.comp); the
// CPU's share of a call is checking its arguments, copying the lights into a buffer and
// setting uniforms, and it does not grow with what the GPU does per light. The sun-map method
// is in EngineTextureMask.cpp, the flares in EngineDraw.cpp.
#include <algorithm>
#include <cmath>

#include "engine/EngineImpl.h"
#include "engine/EngineInput.h"
#include "engine/GlStateGuard.h"

namespace flarekit::engine {

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
    impl->tiles = makeBuffer(GLsizeiptr(maxLights) * FK_MAX_VIEWS * GLsizeiptr(sizeof(int)));
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

Result<int> Engine::loadPresetJson(const char* json, std::size_t length) {
    if (!json) return invalidInput("json: expected preset JSON text, got NULL");
    auto preset = parsePreset(std::string(json, length), "json");
    if (!preset) return preset.error();
    LoadedPreset p;
    p.preset = std::move(*preset);
    m->presets.push_back(std::move(p));
    return int(m->presets.size()) - 1;
}

Status Engine::setSamples(int perSide) {
    if (Status s = checkSamplesPerSide(perSide); !s) return s;
    m->samplesPerSide = perSide;
    return Ok{};
}

Status Engine::setTemporal(float attackSeconds, float releaseSeconds, float guardBand) {
    return setTemporalParams(m->temporal, attackSeconds, releaseSeconds, guardBand);
}

Status Engine::setTransmittance(int view, unsigned texture) {
    if (Status s = checkView(view); !s) return s;
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
    if (Status s = checkView(view); !s) return s;
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
    for (std::size_t v = 0; v < frames.size(); ++v) {
        const int view = int(v);
        if (m->assignTiles(view, frames[v], depth[v].samples, lights, count) > 0)
            if (Status s = m->measureSunMaps(view, frames[v], lights, count, lightBuffer); !s)
                return s;
        if (!m->textureMask) m->measureDepth(view, frames[v], depth[v], count, lightBuffer);
    }
    // The application's shaders (texelFetch of the coverage texture), the flare draw and
    // read-backs all see the stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return Ok{};
}

void Engine::Impl::measureDepth(int view, const fk_frame& f, const DepthTextureInfo& depth,
                                int count, GLuint lightBuffer) {
    // The sun-map pass, or an occluder callback, may have bound anything: bind it all here.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStateBinding, state.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTilesBinding, tiles.get());
    glBindImageTexture(kStateImageUnit, coverageImage.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    const CoverageProgram& c = coverage[depth.multisample ? 1 : 0];
    const GLuint p = c.program.get();
    c.pass.set(p, f, view, maxLights, temporal, guardBand[std::size_t(view)]);
    glProgramUniform1i(p, c.perSide, samplesPerSide);
    glProgramUniform1i(p, c.depthSamples, depth.samples);
    glProgramUniform2f(p, c.textureSize, float(f.width), float(f.height));
    const GLuint kept = transmittance[std::size_t(view)];
    glProgramUniform1i(p, c.hasTransmittance, kept != 0 ? 1 : 0);
    glBindTextureUnit(kTransmittanceUnit, kept);
    glBindSampler(kTransmittanceUnit, linear.get());
    if (depth.multisample) {
        const SamplePattern& pattern = patternFor(f.depth_texture, depth.samples);
        glProgramUniform1i(p, c.sampleCount, depth.samples);
        glProgramUniform2fv(p, c.samplePositions, depth.samples, pattern.positions.data());
    }
    // A depth-stencil texture may be set to hand out stencil: read its depth, then put the
    // application's mode back.
    GLint mode = GL_DEPTH_COMPONENT;
    glGetTextureParameteriv(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
    if (mode != GL_DEPTH_COMPONENT)
        glTextureParameteri(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    glBindTextureUnit(kDepthUnit, f.depth_texture);
    glBindSampler(kDepthUnit, nearest.get());
    glUseProgram(p);
    glDispatchCompute(GLuint(count), 1, 1);
    if (mode != GL_DEPTH_COMPONENT)
        glTextureParameteri(f.depth_texture, GL_DEPTH_STENCIL_TEXTURE_MODE, mode);
}

Result<int> Engine::readView(int view, float* coverage, float* inFrame, float* filtered,
                             int count) {
    if (Status s = checkView(view); !s) return s.error();
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
