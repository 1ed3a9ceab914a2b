// SPDX-License-Identifier: Apache-2.0
// GpuSpriteFlare: each element is rendered once on the CPU (renderElement, the kernels of
// renderFlare) into a texture, then drawn every frame through the engine API's instanced flare
// draw (engine/FlareDraw.h) with the sun as its one light: the same shader places and weighs
// the quads for one sun as for an application's thousand lights. With the element centre on
// a pixel centre the texels land on pixels one to one and the result equals renderFlare's;
// elsewhere bilinear filtering shifts it by the sub-pixel offset.
#include <cmath>
#include <vector>

#include "engine/EngineInput.h"
#include "engine/EnginePrograms.h"
#include "engine/FlareDraw.h"
#include "engine/GlStateGuard.h"
#include "flare/ElementSprites.h"
#include "flarekit/Color.h"
#include "flarekit/gl/EngineScene.h"
#include "flarekit/gl/GpuFlare.h"
#include "gl/GlObjects.h"
#include "scene/CameraMath.h"
#include "scene/SceneTargets.h"

namespace flarekit {

namespace {
//! The sun as the engine's one light: white at the sun's luminance, so the shader's flux is
//! sunFlareScale's and its tint is 1 (renderFlare draws a preset's own colours).
fk_light sunLight(const Scene& view) {
    const Vec3 radiance = view.sun.color * view.sun.intensity;
    fk_light l{};
    l.type = FK_LIGHT_DIRECTIONAL;
    l.direction[0] = float(view.sun.direction.x);
    l.direction[1] = float(view.sun.direction.y);
    l.direction[2] = float(view.sun.direction.z);
    l.radius = float(view.sun.angularRadiusDeg);
    l.color[0] = l.color[1] = l.color[2] = 1.f;
    l.intensity = luminance(float(radiance.x), float(radiance.y), float(radiance.z));
    l.preset = 0;
    return l;
}
}  // namespace

struct GpuSpriteFlare::Impl {
    int height = 0;
    engine::FlareProgram program;
    gl::Buffer light;  //!< the one Light record (light_view.glsl)
    gl::VertexArray vao;
    std::vector<ElementSprite> sprites;
    std::vector<float> packed;
};

Result<GpuSpriteFlare> GpuSpriteFlare::create(const Preset& preset, int height) {
    if (Status s = gl::requireCurrentContext("GpuSpriteFlare::create"); !s) return s.error();
    if (height < 1) return invalidInput("sprite flare: frame height must be positive");
    auto program = engine::linkFlare();
    if (!program) return program.error();
    auto m = std::make_unique<Impl>();
    m->height = height;
    m->program = std::move(*program);
    m->vao = gl::makeVertexArray();
    auto sprites = buildElementSprites(preset, height);
    if (!sprites) return sprites.error();
    m->sprites = std::move(*sprites);
    const fk_light none{};
    engine::packLights(&none, 1, m->packed);
    m->light = engine::makeBuffer(GLsizeiptr(m->packed.size() * sizeof(float)));
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
    const fk_frame frame = engineFrame(view, target);
    const fk_light sun = sunLight(view);
    engine::packLights(&sun, 1, m->packed);
    glNamedBufferSubData(m->light.get(), 0, GLsizeiptr(m->packed.size() * sizeof(float)),
                         m->packed.data());

    glBindFramebuffer(GL_FRAMEBUFFER, sceneTargets(target).framebuffer);
    glViewport(0, 0, target.width(), target.height());
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, engine::kLightsBinding, m->light.get());
    glBindTextureUnit(engine::kCoverageUnit, weight.texture);
    glBindSampler(engine::kCoverageUnit, 0);
    glBindSampler(engine::kElementUnit, 0);
    glBindVertexArray(m->vao.get());
    if (conditionQuery) glBeginConditionalRender(conditionQuery, GL_QUERY_NO_WAIT);
    engine::FlareDraw d;
    d.frame = &frame;
    d.lightCount = 1;
    d.coverageChannel = weight.channel;
    d.fadeAtEdges = false;
    d.elementBlends = true;
    engine::drawFlareElements(m->program, m->sprites, d);
    if (conditionQuery) glEndConditionalRender();
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = gl::checkError("drawing the sprite flare"); !s) return s.error();
    return result;
}

}  // namespace flarekit
