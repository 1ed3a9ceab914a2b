// SPDX-License-Identifier: Apache-2.0
#include "engine/EnginePrograms.h"

#include <string>

#include "flarekit_shaders.h"

namespace flarekit::engine {

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

namespace {

//! The shader after the light_view.glsl prelude (and, for the occlusion passes, the per-light
//! state of light_state.glsl).
std::string withPrelude(const char* text, const std::string& defines, bool state) {
    std::string body(text);
    if (body.rfind("#version", 0) == 0) body = body.substr(body.find('\n') + 1);
    return "#version 450 core\n" + defines + shaders::backend_glsl + shaders::light_view_glsl +
           (state ? shaders::light_state_glsl : "") + "\n#line 2\n" + body;
}

//! A shader without the light prelude, after backend.glsl's definitions alone.
std::string withBackend(const char* text) {
    std::string body(text);
    if (body.rfind("#version", 0) == 0) body = body.substr(body.find('\n') + 1);
    return std::string("#version 450 core\n") + shaders::backend_glsl + "\n#line 2\n" + body;
}

//! An occlusion pass (the per-light state included) and its shared uniforms.
template <class Program>
Result<Program> linkOcclusionPass(const char* name, const char* text, const std::string& defines) {
    auto p = gl::linkProgram({{GL_COMPUTE_SHADER, name, withPrelude(text, defines, true)}});
    if (!p) return p.error();
    Program c;
    c.program = std::move(*p);
    c.pass.locate(c.program.get());
    return c;
}

}  // namespace

Result<CoverageProgram> linkCoverage(bool multisample) {
    auto c = linkOcclusionPass<CoverageProgram>("light_coverage.comp", shaders::light_coverage_comp,
                                                multisample ? "#define MULTISAMPLE\n" : "");
    if (!c) return c.error();
    const GLuint n = c->program.get();
    c->perSide = gl::uniformLocation(n, "perSide");
    c->depthSamples = gl::uniformLocation(n, "samplesPerPixel");
    c->hasTransmittance = gl::uniformLocation(n, "hasTransmittance");
    c->textureSize = gl::uniformLocation(n, "depthTextureSize");
    if (multisample) {
        c->sampleCount = gl::uniformLocation(n, "sampleCount");
        c->samplePositions = gl::uniformLocation(n, "samplePositions");
    }
    return c;
}

Result<SunMapProgram> linkSunMap() {
    auto c =
        linkOcclusionPass<SunMapProgram>("sunmap_coverage.comp", shaders::sunmap_coverage_comp, "");
    if (!c) return c.error();
    c->tileSize = gl::uniformLocation(c->program.get(), "tileSize");
    c->tilesPerRow = gl::uniformLocation(c->program.get(), "tilesPerRow");
    return c;
}

Result<FlareProgram> linkFlare() {
    auto p = gl::linkProgram(
        {{GL_VERTEX_SHADER, "light_flare.vert", withPrelude(shaders::light_flare_vert, "", false)},
         {GL_FRAGMENT_SHADER, "light_flare.frag", withBackend(shaders::light_flare_frag)}});
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
    f.coverageChannel = gl::uniformLocation(n, "coverageChannel");
    f.fadeAtEdges = gl::uniformLocation(n, "fadeAtEdges");
    return f;
}

}  // namespace flarekit::engine
