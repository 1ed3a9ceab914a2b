// SPDX-License-Identifier: Apache-2.0
#include "occlusion/FrameDepth.h"
#include "scene/SceneTargets.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"

namespace flarekit::occlusion {

namespace {
//! The implementation's sample positions for `samples` per pixel, read once from a
//! framebuffer of that many samples (GL 4.5 fixes them per sample count and format; the scene
//! renderer's colour target is RGBA16F).
const std::vector<float>& samplePositions(int samples) {
    static std::map<int, std::vector<float>> cache;
    auto it = cache.find(samples);
    if (it != cache.end()) return it->second;
    GLuint texture = 0, framebuffer = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &texture);
    glTextureStorage2DMultisample(texture, samples, GL_RGBA16F, 1, 1, GL_TRUE);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    std::vector<float> positions;
    for (int i = 0; i < samples; ++i) {
        float p[2] = {0.5f, 0.5f};
        glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), p);
        positions.insert(positions.end(), {p[0], p[1]});
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
    return cache.emplace(samples, std::move(positions)).first->second;
}
}  // namespace

Result<FrameDepthProgram> FrameDepthProgram::link(std::initializer_list<gl::ShaderSource> sources) {
    FrameDepthProgram p;
    for (bool multisample : {false, true}) {
        auto program =
            linkWithDisc(sources, std::string(multisample ? "#define MULTISAMPLE\n" : "") +
                                      shaders::frame_depth_glsl);
        if (!program) return program.error();
        p.m_variants[multisample] = std::move(*program);
    }
    return p;
}

void FrameDepthProgram::bindDepth(const SceneRenderer& renderer) const {
    const int samples = renderer.msaaSamples();
    if (samples <= 1) {
        glBindTextureUnit(0, sceneTargets(renderer).depth);
        return;
    }
    const GLuint program = forFrame(renderer);
    const std::vector<float>& positions = samplePositions(samples);
    const int n = std::min(samples, 16);
    glProgramUniform1i(program, gl::uniformLocation(program, "frameSampleCount"), n);
    glProgramUniform2fv(program, gl::uniformLocation(program, "frameSamplePositions"), n,
                        positions.data());
    glBindTextureUnit(0, sceneTargets(renderer).multisampleDepth);
}

}  // namespace flarekit::occlusion
