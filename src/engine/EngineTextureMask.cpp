// SPDX-License-Identifier: Apache-2.0
// Sun maps through the engine: the application's occluder callback draws the tile of each
// light they measure (SunMapAtlas: every light with texture-mask, the small ones with
// compute), and one dispatch of sunmap_coverage.comp reduces them all.
#include "engine/EngineImpl.h"
#include "engine/GlStateGuard.h"
#include "engine/TileChoice.h"

namespace flarekit::engine {

int Engine::Impl::assignTiles(int view, const fk_frame& f, int depthSamples, const fk_light* lights,
                              int count) {
    // Without an occluder callback nothing can draw a tile: every light on the depth.
    const int tiled = chooseTiles(f, depthSamples, lights, count, occluders && textureMask,
                                  occluders ? tileBelow : 0, tileOf);
    glNamedBufferSubData(tiles.get(), GLintptr(view) * maxLights * GLintptr(sizeof(int)),
                         GLsizeiptr(count * sizeof(int)), tileOf.data());
    return tiled;
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
    m->textureMask = true;
    return Ok{};
}

Status Engine::setOccluderCallback(fk_occluder_callback callback, void* user) {
    m->occluders = callback;
    m->occludersUser = user;
    return Ok{};
}

Status Engine::setTileThreshold(int depthSamples) {
    if (depthSamples < 0 || depthSamples > kMaxTileBelow) {
        return invalidInput("tile-below: expected 0.." + std::to_string(kMaxTileBelow) +
                            " depth samples, got " + std::to_string(depthSamples));
    }
    m->tileBelow = depthSamples;
    return Ok{};
}

Status Engine::Impl::measureSunMaps(int view, const fk_frame& f, const fk_light* lights, int count,
                                    GLuint lightBuffer) {
    if (!sunMaps) {
        auto atlas = SunMapAtlas::create(maxLights);
        if (!atlas) return atlas.error();
        sunMaps = std::move(*atlas);
    }
    sunMaps->draw(view, f, lights, tileOf.data(), count, occluders, occludersUser);
    // The callbacks may have bound anything: bind what the reduction reads now.
    const SunMapProgram& c = sunMap;
    const GLuint p = c.program.get();
    c.pass.set(p, f, view, maxLights, temporal, false);
    glProgramUniform1i(p, c.tileSize, sunMaps->tileSize());
    glProgramUniform1i(p, c.tilesPerRow, sunMaps->tilesPerRow());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStateBinding, state.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTilesBinding, tiles.get());
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
