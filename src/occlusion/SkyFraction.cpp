// SPDX-License-Identifier: Apache-2.0
#include "occlusion/SkyFraction.h"
#include "scene/SceneTargets.h"

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"

namespace flarekit::occlusion {

Result<SkyFraction> SkyFraction::create() {
    SkyFraction s;
    auto ms = linkFullscreen("sky_fraction.frag (MSAA)", shaders::sky_fraction_frag,
                             "#define MULTISAMPLE\n");
    if (!ms) return ms.error();
    auto single = linkFullscreen("sky_fraction.frag", shaders::sky_fraction_frag);
    if (!single) return single.error();
    s.m_multisample = std::move(*ms);
    s.m_single = std::move(*single);
    s.m_vao = gl::makeVertexArray();
    return s;
}

Result<GLuint> SkyFraction::update(const SunDiscView& v, const SceneRenderer& renderer) {
    if (renderer.width() != m_width || renderer.height() != m_height) {
        m_texture = gl::makeTexture2D(GL_R32F, renderer.width(), renderer.height());
        auto fb = gl::makeFramebuffer(m_texture);
        if (!fb) return fb.error();
        m_target = std::move(*fb);
        m_width = renderer.width(), m_height = renderer.height();
    }
    const bool multisampled = renderer.msaaSamples() > 1;
    const GLuint p = multisampled ? m_multisample.get() : m_single.get();
    if (multisampled)
        glProgramUniform1i(p, gl::uniformLocation(p, "sampleCount"), renderer.msaaSamples());
    glProgramUniform1f(p, gl::uniformLocation(p, "lightDepth"), float(v.lightDepth));
    glBindFramebuffer(GL_FRAMEBUFFER, m_target.get());
    glViewport(0, 0, m_width, m_height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindTextureUnit(
        0, multisampled ? sceneTargets(renderer).multisampleDepth : sceneTargets(renderer).depth);
    glBindVertexArray(m_vao.get());
    glUseProgram(p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = gl::checkError("sky fraction pass"); !s) return s.error();
    return m_target.get();
}

}  // namespace flarekit::occlusion
