// SPDX-License-Identifier: Apache-2.0
// The instanced flares: each used preset's sprites over every light (engine/FlareDraw.h).
#include "engine/EngineImpl.h"
#include "engine/EngineInput.h"
#include "engine/FlareDraw.h"
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
    // Drawing needs the frame's matrices and viewport, not its depth texture.
    if (Status s = checkFrameNumbers(frame, "frame"); !s) return s;
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
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(frame->viewport[0], frame->viewport[1], frame->viewport[2], frame->viewport[3]);
    setAdditiveDrawState();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, lightBuffer);
    glBindTextureUnit(kCoverageUnit, m->coverageImage.get());
    glBindSampler(kCoverageUnit, m->nearest.get());
    glBindSampler(kElementUnit, 0);  // the element textures' own filtering and border
    glBindVertexArray(m->vertexArray.get());
    FlareDraw d;
    d.frame = frame;
    d.view = view;
    d.lightCount = count;
    d.guardBand = float(m->temporal.guardBand);
    for (std::size_t id = 0; id < m->presets.size(); ++id) {
        if (!used[id]) continue;
        d.presetId = int(id);
        drawFlareElements(m->flare, m->presets[id].sprites, d);
    }
    return Ok{};
}

}  // namespace flarekit::engine
