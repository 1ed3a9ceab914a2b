// SPDX-License-Identifier: Apache-2.0
// GpuSpriteFlare: each element is rendered once on the CPU (renderElement, the kernels of
// renderFlare) into a texture, then drawn every frame as a quad centred where renderFlare puts
// it. With the element centre on a pixel centre the texels land on pixels one to one and the
// result equals renderFlare's; elsewhere bilinear filtering shifts it by the sub-pixel offset.
#include <algorithm>
#include <cmath>
#include <vector>

#include "flare/ElementSprites.h"
#include "flarekit/gl/GpuFlare.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "scene/CameraMath.h"
#include "scene/SceneTargets.h"

namespace flarekit {

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

struct GpuSpriteFlare::Impl {
    int height = 0;
    gl::Program program;
    gl::VertexArray vao;
    std::vector<ElementSprite> sprites;
};

Result<GpuSpriteFlare> GpuSpriteFlare::create(const Preset& preset, int height) {
    if (Status s = gl::requireCurrentContext("GpuSpriteFlare::create"); !s) return s.error();
    if (height < 1) return invalidInput("sprite flare: frame height must be positive");
    auto program =
        gl::linkProgram({{GL_VERTEX_SHADER, "sprite_flare.vert", shaders::sprite_flare_vert},
                         {GL_FRAGMENT_SHADER, "sprite_flare.frag", shaders::sprite_flare_frag}});
    if (!program) return program.error();
    auto m = std::make_unique<Impl>();
    m->height = height;
    m->program = std::move(*program);
    m->vao = gl::makeVertexArray();
    auto sprites = buildElementSprites(preset, height);
    if (!sprites) return sprites.error();
    m->sprites = std::move(*sprites);
    return GpuSpriteFlare(std::move(m));
}

GpuSpriteFlare::GpuSpriteFlare(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
GpuSpriteFlare::~GpuSpriteFlare() = default;
GpuSpriteFlare::GpuSpriteFlare(GpuSpriteFlare&&) noexcept = default;
GpuSpriteFlare& GpuSpriteFlare::operator=(GpuSpriteFlare&&) noexcept = default;

std::size_t GpuSpriteFlare::elementCount() const {
    return m->sprites.size();
}

Result<FlaredFrame> GpuSpriteFlare::draw(const SceneRenderer& target, const Scene& view,
                                         GpuChannel weight, unsigned conditionQuery) const {
    if (target.height() != m->height)
        return invalidInput("sprite flare: made for another frame height");
    if (!weight || weight.channel < 0 || weight.channel > 3) {
        return invalidInput("sprite flare: expected a weight texture and a channel 0..3");
    }
    FlaredFrame result;
    result.sunInFront = projectDirection(view, view.sun.direction, result.sunPixel);
    result.flareIntensity = sunFlareScale(view);
    if (!result.sunInFront || !std::isfinite(result.sunPixel.x) ||
        !std::isfinite(result.sunPixel.y))
        return result;
    const GLuint p = m->program.get();
    const int w = target.width(), h = target.height();
    glProgramUniform1i(p, gl::uniformLocation(p, "weightChannel"), weight.channel);
    glProgramUniform1f(p, gl::uniformLocation(p, "brightnessScale"), result.flareIntensity);
    glProgramUniform2f(p, gl::uniformLocation(p, "frameSize"), float(w), float(h));
    const GLint centreAt = gl::uniformLocation(p, "centre"),
                halfAt = gl::uniformLocation(p, "halfSize"),
                weightAt = gl::uniformLocation(p, "elementWeight"),
                transposedAt = gl::uniformLocation(p, "transposed");

    glBindFramebuffer(GL_FRAMEBUFFER, sceneTargets(target).framebuffer);
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBindTextureUnit(1, weight.texture);
    glBindVertexArray(m->vao.get());
    glUseProgram(p);
    if (conditionQuery) glBeginConditionalRender(conditionQuery, GL_QUERY_NO_WAIT);
    for (const ElementSprite& s : m->sprites) {
        // Top-left origin, as renderFlare places elements.
        const EdgePlacement edge = s.edgeStreak
                                       ? edgeStreakPlacement(result.sunPixel, w, h, s.reach)
                                       : EdgePlacement{{}, 0.f, 1.f};
        const Point c = s.edgeStreak ? edge.centre : flareVectorPoint(result.sunPixel, w, h, s.t);
        if (edge.weight <= 0.f) continue;
        glProgramUniform2f(p, centreAt, c.x, float(h) - c.y);
        glProgramUniform1f(p, weightAt, edge.weight);
        glProgramUniform1i(p, transposedAt, edge.rotationDeg != 0.f ? 1 : 0);
        glProgramUniform2f(p, halfAt, s.halfW, s.halfH);
        setBlend(s.blend);
        glBindTextureUnit(0, s.texture.get());
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    if (conditionQuery) glEndConditionalRender();
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = gl::checkError("drawing the sprite flare"); !s) return s.error();
    return result;
}

}  // namespace flarekit
