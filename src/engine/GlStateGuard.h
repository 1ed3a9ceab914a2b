// SPDX-License-Identifier: Apache-2.0
// The application's GL state, saved when an engine API call starts and put back when it ends:
// the bound framebuffers, program, vertex array, viewport, the texture, sampler, image and
// storage-buffer bindings the engine uses, and every switch its passes touch (blend per draw
// buffer, depth, stencil, scissor, cull, polygon mode, colour masks, sample coverage,
// rasterizer discard, logic op). Engines keep their own state caches; a call that changes
// none of it leaves those caches true.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>

namespace flarekit::engine {

//! Texture units, image unit and storage-buffer bindings the engine's shaders use: the top of
//! the ranges GL 4.5 guarantees (80 texture units, 8 image units, 8 storage bindings), where
//! applications rarely keep their own bindings.
inline constexpr GLuint kElementUnit = 12, kCoverageUnit = 13, kTransmittanceUnit = 14,
                        kDepthUnit = 15;
inline constexpr GLuint kStateImageUnit = 7;
inline constexpr GLuint kTilesBinding = 5, kLightsBinding = 6, kStateBinding = 7;
//! Draw buffers whose blend and colour mask are saved: the GL 4.5 minimum of GL_MAX_DRAW_BUFFERS.
inline constexpr int kSavedDrawBuffers = 8;

class GlStateGuard {
  public:
    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

  private:
    struct TextureUnit {
        GLint texture2D = 0, textureMultisample = 0, sampler = 0;
    };
    struct DrawBuffer {
        GLboolean blend = GL_FALSE;
        GLint srcRgb = GL_ONE, dstRgb = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;
        GLint equationRgb = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
        GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    };
    struct StorageBinding {
        GLint buffer = 0;
        GLint64 start = 0, size = 0;
    };
    GLint m_program = 0, m_vertexArray = 0, m_drawFramebuffer = 0, m_readFramebuffer = 0;
    GLint m_viewport[4] = {0, 0, 0, 0};
    GLint m_activeTexture = GL_TEXTURE0;
    std::array<TextureUnit, 4> m_units;  //!< kElementUnit .. kDepthUnit
    GLint m_imageName = 0, m_imageLevel = 0, m_imageLayer = 0, m_imageAccess = GL_READ_ONLY,
          m_imageFormat = GL_R32F;
    GLboolean m_imageLayered = GL_FALSE;
    std::array<StorageBinding, 3> m_storage;  //!< kTilesBinding, kLightsBinding, kStateBinding
    GLint m_storageGeneric = 0;
    std::array<DrawBuffer, kSavedDrawBuffers> m_drawBuffers;
    GLboolean m_depthTest = GL_FALSE, m_depthMask = GL_TRUE, m_stencilTest = GL_FALSE,
              m_scissorTest = GL_FALSE, m_cullFace = GL_FALSE, m_rasterizerDiscard = GL_FALSE,
              m_alphaToCoverage = GL_FALSE, m_sampleMask = GL_FALSE, m_logicOp = GL_FALSE;
    GLint m_polygonMode[2] = {GL_FILL, GL_FILL};
};

//! Puts the pipeline switches the engine's draw needs: additive blend into draw buffer 0
//! only, no depth, stencil, scissor, culling or sample tricks, filled polygons.
void setAdditiveDrawState();

}  // namespace flarekit::engine
