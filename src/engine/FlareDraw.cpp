// SPDX-License-Identifier: Apache-2.0
#include "engine/FlareDraw.h"

#include "engine/GlStateGuard.h"

namespace flarekit::engine {

namespace {
void setBlend(BlendMode mode) {
    // Premultiplied source, the same equations as compositeSpan (Blend.h). Add keeps the
    // destination's alpha; Screen and Over combine alpha as Porter-Duff over.
    switch (mode) {
        case BlendMode::Add:
            glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
            break;
        case BlendMode::Screen:
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_COLOR, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case BlendMode::Over:
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
    }
}
}  // namespace

void drawFlareElements(const FlareProgram& f, std::span<const ElementSprite> sprites,
                       const FlareDraw& d) {
    const GLuint p = f.program.get();
    glProgramUniformMatrix4fv(p, f.view, 1, GL_FALSE, d.frame->view);
    glProgramUniformMatrix4fv(p, f.projection, 1, GL_FALSE, d.frame->projection);
    glProgramUniform4iv(p, f.viewport, 1, d.frame->viewport);
    glProgramUniform1i(p, f.convention, int(d.frame->depth_convention));
    glProgramUniform1i(p, f.viewIndex, d.view);
    glProgramUniform1i(p, f.presetId, d.presetId);
    glProgramUniform1i(p, f.coverageChannel, d.coverageChannel);
    glProgramUniform1i(p, f.fadeAtEdges, d.fadeAtEdges ? 1 : 0);
    glProgramUniform1f(p, f.guardBand, d.guardBand);
    glProgramUniform1f(p, f.referenceFlux, float(kReferenceFlux));
    glUseProgram(p);
    for (const ElementSprite& s : sprites) {
        glProgramUniform1f(p, f.t, s.t);
        glProgramUniform2f(p, f.halfSize, s.halfW, s.halfH);
        glProgramUniform1i(p, f.edgeStreak, s.edgeStreak ? 1 : 0);
        glProgramUniform1f(p, f.reach, s.reach);
        if (d.elementBlends) setBlend(s.blend);
        glBindTextureUnit(kElementUnit, s.texture.get());
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, d.lightCount);
    }
}

}  // namespace flarekit::engine
