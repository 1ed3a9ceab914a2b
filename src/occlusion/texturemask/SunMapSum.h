// SPDX-License-Identifier: Apache-2.0
// The half of GPG2 texture masking that both texture-mask methods share: an N x N sun map
// (R: sun visible, G: texel in the disc), summed by points into a 1x1 intensity map with
// additive blending, then resolved to coverage = R / G in a 1x1 R32F texture. No CPU read-back
// anywhere. As in the seed, a binary map sums exactly in 8 bits (RGBA8 targets); a fractional
// map (texels partly covered: multisampled, or sub-sampled from the frame) is RGBA16F and sums
// into an RGBA32F intensity map, since 8 bits would round each small addition away.
#pragma once

#include <string>
#include <vector>

#include "flarekit/gl/GpuVisibility.h"
#include "gl/GlObjects.h"
#include "occlusion/SunDisc.h"

namespace flarekit::occlusion {

struct SunMapLayout {
    int size = 16;               //!< sun map side, texels
    bool bilinear = false;       //!< samples average 2x2 texels through GL_LINEAR
    std::vector<float> samples;  //!< texture coordinates, xy pairs
    float unit = 1.f / 255.f;    //!< what one full sample adds in the 8-bit intensity map
    bool fractional = false;     //!< texels hold fractions: float targets, every texel summed
    int msaaSamples = 1;         //!< MSAA samples of the sun map (> 1 makes it fractional)
};

//! "square": 16x16, a point per texel (the seed's 256). "circle": 18x18, points only on
//! texels whose centre is in the disc (at most 255, so an 8-bit sum cannot overflow).
//! "bilinear": 16x16, 64 points on the corners shared by 2x2 blocks. With `samples` > 1 the
//! map is multisampled and fractional; "circle" then sums every texel, its G weighing the
//! rim texels by the share of their samples in the disc.
Result<SunMapLayout> sunMapLayout(const std::string& variant, int samples = 1,
                                  bool fractional = false);

//! The sun camera: at the eye, looking at the sun, a square frustum the disc exactly fills.
SceneCamera sunCamera(const Scene& view);

class SunMapSum {
  public:
    static Result<SunMapSum> create(SunMapLayout layout);
    int size() const { return m_layout.size; }
    int samples() const { return m_layout.msaaSamples; }
    //! Where the sun map is drawn (multisampled when samples() > 1).
    GLuint sunMapFramebuffer() const {
        return m_layout.msaaSamples > 1 ? m_msTarget.get() : m_mapTarget.get();
    }
    //! Resolves a multisampled map, sums the sun map and writes the coverage into `coverage` (1x1
    //! R32F texture).
    Status sumInto(GLuint coverage);
    //! The sun map (resolved when multisampled) and the intensity map of the last sumInto().
    std::vector<MethodView> views() const;

  private:
    SunMapLayout m_layout;
    gl::Texture m_map, m_intensity, m_msMap;
    gl::Framebuffer m_msTarget, m_mapTarget, m_intensityTarget, m_coverageTarget;
    GLuint m_coverageAttached = 0;
    gl::Buffer m_samples;
    gl::Program m_sum, m_resolve;
    gl::VertexArray m_vao;
};

}  // namespace flarekit::occlusion
