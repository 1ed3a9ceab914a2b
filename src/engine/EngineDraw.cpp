// SPDX-License-Identifier: Apache-2.0
// The instanced flares: per preset element one glDrawArraysInstanced over every light
// (light_flare.vert places and weighs each instance from the coverage texture).
#include "engine/EngineImpl.h"
#include "engine/EngineInput.h"
#include "engine/GlStateGuard.h"

namespace flarekit::engine {

Status Engine::Impl::ensureSprites(LoadedPreset& p, int height) {
    if (p.spriteHeight == height) return Ok{};
    auto sprites = buildElementSprites(p.preset, height);
    if (!sprites) return sprites.error();
    p.sprites = std::move(*sprites);
    p.spriteHeight = height;
    return Ok{};
}

Status Engine::draw(int view, const fk_frame* frame, const fk_light* lights, int count,
                    unsigned framebuffer) {
    if (Status s = checkView(view); !s) return s;
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

}  // namespace flarekit::engine
