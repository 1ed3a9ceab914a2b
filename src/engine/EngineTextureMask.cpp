// SPDX-License-Identifier: Apache-2.0
// texture-mask through the engine: the application's occluder callback draws each light's
// sun map (SunMapAtlas), and one dispatch of sunmap_coverage.comp reduces them all.
#include "engine/EngineImpl.h"
#include "engine/GlStateGuard.h"

namespace flarekit::engine {

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
    if (!m->sunMaps) {
        const GlStateGuard guard;
        auto atlas = SunMapAtlas::create(m->maxLights);
        if (!atlas) return atlas.error();
        m->sunMaps = std::move(*atlas);
    }
    m->textureMask = true;
    return Ok{};
}

Status Engine::setOccluderCallback(fk_occluder_callback callback, void* user) {
    m->occluders = callback;
    m->occludersUser = user;
    return Ok{};
}

Status Engine::Impl::measureSunMaps(int view, const fk_frame& f, const fk_light* lights, int count,
                                    GLuint lightBuffer) {
    sunMaps->draw(view, f, lights, count, occluders, occludersUser);
    // The callbacks may have bound anything: bind what the reduction reads now.
    const SunMapProgram& c = sunMap;
    const GLuint p = c.program.get();
    c.pass.set(p, f, view, maxLights, temporal, false);
    glProgramUniform1i(p, c.tileSize, sunMaps->tileSize());
    glProgramUniform1i(p, c.tilesPerRow, sunMaps->tilesPerRow());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStateBinding, state.get());
    glBindImageTexture(kStateImageUnit, coverageImage.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    // The reduction reads the atlas where the compute pass reads depth (drawing, then sampling
    // what was drawn, needs no barrier).
    glBindTextureUnit(kDepthUnit, sunMaps->texture());
    glBindSampler(kDepthUnit, nearest.get());
    glUseProgram(p);
    glDispatchCompute(GLuint(count), 1, 1);
    return Ok{};
}

}  // namespace flarekit::engine
