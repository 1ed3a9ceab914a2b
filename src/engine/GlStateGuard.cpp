// SPDX-License-Identifier: Apache-2.0
#include "engine/GlStateGuard.h"

namespace flarekit::engine {

namespace {
void setEnabled(GLenum cap, GLboolean on) {
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
}
constexpr GLuint kUnits[4] = {kElementUnit, kCoverageUnit, kTransmittanceUnit, kDepthUnit};
constexpr GLuint kStorage[3] = {kTilesBinding, kLightsBinding, kStateBinding};
}  // namespace

GlStateGuard::GlStateGuard() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &m_program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &m_vertexArray);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_drawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &m_readFramebuffer);
    glGetIntegerv(GL_VIEWPORT, m_viewport);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &m_activeTexture);
    for (std::size_t i = 0; i < m_units.size(); ++i) {
        glActiveTexture(GL_TEXTURE0 + kUnits[i]);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &m_units[i].texture2D);
        glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &m_units[i].textureMultisample);
        glGetIntegerv(GL_SAMPLER_BINDING, &m_units[i].sampler);
    }
    glActiveTexture(GLenum(m_activeTexture));
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, kStateImageUnit, &m_imageName);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, kStateImageUnit, &m_imageLevel);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, kStateImageUnit, &m_imageLayer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, kStateImageUnit, &m_imageAccess);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, kStateImageUnit, &m_imageFormat);
    glGetBooleani_v(GL_IMAGE_BINDING_LAYERED, kStateImageUnit, &m_imageLayered);
    for (std::size_t i = 0; i < m_storage.size(); ++i) {
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, kStorage[i], &m_storage[i].buffer);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, kStorage[i], &m_storage[i].start);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, kStorage[i], &m_storage[i].size);
    }
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &m_storageGeneric);
    for (int i = 0; i < kSavedDrawBuffers; ++i) {
        DrawBuffer& d = m_drawBuffers[std::size_t(i)];
        const GLuint u = GLuint(i);
        d.blend = glIsEnabledi(GL_BLEND, u);
        glGetIntegeri_v(GL_BLEND_SRC_RGB, u, &d.srcRgb);
        glGetIntegeri_v(GL_BLEND_DST_RGB, u, &d.dstRgb);
        glGetIntegeri_v(GL_BLEND_SRC_ALPHA, u, &d.srcAlpha);
        glGetIntegeri_v(GL_BLEND_DST_ALPHA, u, &d.dstAlpha);
        glGetIntegeri_v(GL_BLEND_EQUATION_RGB, u, &d.equationRgb);
        glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, u, &d.equationAlpha);
        glGetBooleani_v(GL_COLOR_WRITEMASK, u, d.mask);
    }
    m_depthTest = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &m_depthMask);
    m_stencilTest = glIsEnabled(GL_STENCIL_TEST);
    m_scissorTest = glIsEnabled(GL_SCISSOR_TEST);
    m_cullFace = glIsEnabled(GL_CULL_FACE);
    m_rasterizerDiscard = glIsEnabled(GL_RASTERIZER_DISCARD);
    m_alphaToCoverage = glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    m_sampleMask = glIsEnabled(GL_SAMPLE_MASK);
    m_logicOp = glIsEnabled(GL_COLOR_LOGIC_OP);
    glGetIntegerv(GL_POLYGON_MODE, m_polygonMode);
}

GlStateGuard::~GlStateGuard() {
    glUseProgram(GLuint(m_program));
    glBindVertexArray(GLuint(m_vertexArray));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(m_drawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(m_readFramebuffer));
    glViewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
    for (std::size_t i = 0; i < m_units.size(); ++i) {
        glActiveTexture(GL_TEXTURE0 + kUnits[i]);
        glBindTexture(GL_TEXTURE_2D, GLuint(m_units[i].texture2D));
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, GLuint(m_units[i].textureMultisample));
        glBindSampler(kUnits[i], GLuint(m_units[i].sampler));
    }
    glActiveTexture(GLenum(m_activeTexture));
    glBindImageTexture(kStateImageUnit, GLuint(m_imageName), m_imageLevel, m_imageLayered,
                       m_imageLayer, GLenum(m_imageAccess), GLenum(m_imageFormat));
    for (std::size_t i = 0; i < m_storage.size(); ++i) {
        const StorageBinding& b = m_storage[i];
        if (b.buffer != 0 && b.size > 0)
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kStorage[i], GLuint(b.buffer),
                              GLintptr(b.start), GLsizeiptr(b.size));
        else
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStorage[i], GLuint(b.buffer));
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(m_storageGeneric));
    for (int i = 0; i < kSavedDrawBuffers; ++i) {
        const DrawBuffer& d = m_drawBuffers[std::size_t(i)];
        const GLuint u = GLuint(i);
        if (d.blend)
            glEnablei(GL_BLEND, u);
        else
            glDisablei(GL_BLEND, u);
        glBlendFuncSeparatei(u, GLenum(d.srcRgb), GLenum(d.dstRgb), GLenum(d.srcAlpha),
                             GLenum(d.dstAlpha));
        glBlendEquationSeparatei(u, GLenum(d.equationRgb), GLenum(d.equationAlpha));
        glColorMaski(u, d.mask[0], d.mask[1], d.mask[2], d.mask[3]);
    }
    setEnabled(GL_DEPTH_TEST, m_depthTest);
    glDepthMask(m_depthMask);
    setEnabled(GL_STENCIL_TEST, m_stencilTest);
    setEnabled(GL_SCISSOR_TEST, m_scissorTest);
    setEnabled(GL_CULL_FACE, m_cullFace);
    setEnabled(GL_RASTERIZER_DISCARD, m_rasterizerDiscard);
    setEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE, m_alphaToCoverage);
    setEnabled(GL_SAMPLE_MASK, m_sampleMask);
    setEnabled(GL_COLOR_LOGIC_OP, m_logicOp);
    // Core profiles set both faces together; GL_POLYGON_MODE reports that one mode twice.
    glPolygonMode(GL_FRONT_AND_BACK, GLenum(m_polygonMode[0]));
}

void setAdditiveDrawState() {
    for (int i = 0; i < kSavedDrawBuffers; ++i) {
        const GLuint u = GLuint(i);
        const GLboolean on = i == 0 ? GL_TRUE : GL_FALSE;
        glColorMaski(u, on, on, on, on);
    }
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    glBlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_SAMPLE_MASK);
    glDisable(GL_COLOR_LOGIC_OP);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

}  // namespace flarekit::engine
