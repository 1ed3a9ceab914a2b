// The half of GPG2 texture masking that both texture-mask methods share: an N x N RGBA8 sun
// map (R: sun visible, G: texel in the disc), summed by points into a 1x1 RGBA8 intensity map
// with additive blending, then resolved to coverage = R / G in a 1x1 R32F texture. No CPU
// read-back anywhere.
#pragma once

#include <string>
#include <vector>

#include "gl/GlObjects.h"
#include "occlusion/SunDisc.h"

namespace flarekit::occlusion {

struct SunMapLayout {
    int size = 16;                  //!< sun map side, texels
    bool bilinear = false;          //!< samples average 2x2 texels through GL_LINEAR
    std::vector<float> samples;     //!< texture coordinates, xy pairs
    float unit = 1.f / 255.f;       //!< what one full sample adds in the 8-bit intensity map
};

//! "square": 16x16, a point per texel (the seed's 256). "circle": 18x18, points only on
//! texels whose centre is in the disc (at most 255, so an 8-bit sum cannot overflow).
//! "bilinear": 16x16, 64 points on the corners shared by 2x2 blocks.
Result<SunMapLayout> sunMapLayout(const std::string& variant);

//! The sun camera: at the eye, looking at the sun, a square frustum the disc exactly fills.
SceneCamera sunCamera(const Scene& view);

class SunMapSum {
public:
    static Result<SunMapSum> create(SunMapLayout layout);
    int size() const { return m_layout.size; }
    GLuint sunMapFramebuffer() const { return m_mapTarget.get(); }
    //! Sums the sun map and writes the coverage into `coverage` (1x1 R32F texture).
    Status sumInto(GLuint coverage);

private:
    SunMapLayout m_layout;
    gl::Texture m_map, m_intensity;
    gl::Framebuffer m_mapTarget, m_intensityTarget, m_coverageTarget;
    GLuint m_coverageAttached = 0;
    gl::Buffer m_samples;
    gl::Program m_sum, m_resolve;
    gl::VertexArray m_vao;
};

}  // namespace flarekit::occlusion
