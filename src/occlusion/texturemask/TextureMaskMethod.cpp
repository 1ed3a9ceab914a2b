// SPDX-License-Identifier: Apache-2.0
// `texture-mask`: GPG2 texture masking as the seed does it. A sun camera at the eye looks
// straight at the sun with a frustum the disc exactly fills; the sun map is cleared, the sun
// drawn white, the occluders in that narrow view (culled on the CPU against the sun's cone)
// drawn black over it, and points sum the map into a 1x1 intensity map on the GPU. Because it
// has its own camera it measures suns outside the frame too. An occluder that surely hides
// the whole cone (a sphere or box whose inner ball covers it) short-cuts to 0 without drawing.
// When the frame is multisampled the sun map takes as many samples, so thin occluders are
// measured to a sample as on screen (SunMapSum: fractional map, float sum).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"
#include "occlusion/texturemask/SunMapSum.h"
#include "scene/CameraMath.h"
#include "scene/SceneMesh.h"
#include "scene/SceneTargets.h"

namespace flarekit::occlusion {

namespace {
class TextureMaskMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create(const Scene& world,
                                                         const std::string& variant) {
        auto m = std::unique_ptr<TextureMaskMethod>(new TextureMaskMethod(variant));
        if (Status s = m->prepare(1); !s) return s.error();  // checks the variant too
        auto black = gl::linkProgram(
            {{GL_VERTEX_SHADER, "scene.vert", shaders::scene_vert},
             {GL_FRAGMENT_SHADER, "occluder_black.frag", shaders::occluder_black_frag}});
        if (!black) return black.error();
        m->m_black = std::move(*black);
        m->m_ranges = sceneMeshRanges(opaqueObjects(world));  // the renderer's depth mesh
        return std::unique_ptr<GpuVisibility>(std::move(m));
    }
    std::string name() const override { return "texture-mask"; }
    int latencyFrames() const override { return 0; }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        m_drewMaps = false;
        if (!cull(view)) {
            publish(0.0);  // early out: one object hides the whole sun
            return Ok{};
        }
        if (Status s = prepare(renderer.msaaSamples()); !s) return s;
        SunMapSum& sum = *m_sum;
        const int n = sum.size();
        const SceneCamera camera = sunCamera(view);
        glBindFramebuffer(GL_FRAMEBUFFER, sum.sunMapFramebuffer());
        glViewport(0, 0, n, n);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        setSunDiscUniforms(m_disc.get(), sunDiscView(camera, n, n, view.sun));
        glBindVertexArray(m_emptyVao.get());
        glUseProgram(m_disc.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);  // the sun, white (and G = disc)
        if (!m_firsts.empty()) {
            const Mat4 vp = multiply(perspectiveMatrix(camera, 1.0), lookAtMatrix(camera));
            const auto vpf = toFloat(vp);
            glProgramUniformMatrix4fv(m_black.get(),
                                      gl::uniformLocation(m_black.get(), "viewProjection"), 1,
                                      GL_FALSE, vpf.data());
            glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);  // occluders blacken R only
            glBindVertexArray(sceneTargets(renderer).meshVertexArray);
            glUseProgram(m_black.get());
            glMultiDrawArrays(GL_TRIANGLES, m_firsts.data(), m_counts.data(),
                              GLsizei(m_firsts.size()));
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        if (Status s = sum.sumInto(coverageName()); !s) return s;
        markPublished();
        m_drewMaps = true;
        return Ok{};
    }
    std::vector<MethodView> views() const override {
        return m_drewMaps ? m_sum->views() : std::vector<MethodView>{};
    }

  private:
    explicit TextureMaskMethod(std::string variant) : m_variant(std::move(variant)) {
        m_emptyVao = gl::makeVertexArray();
    }

    //! The sun map and disc program for a frame of `samples` per pixel (made on first use).
    Status prepare(int samples) {
        samples = std::max(1, samples);
        if (m_sum && m_sum->samples() == samples) return Ok{};
        auto layout = sunMapLayout(m_variant, samples);
        if (!layout) return layout.error();
        auto sum = SunMapSum::create(std::move(*layout));
        if (!sum) return sum.error();
        auto disc =
            linkWithDisc({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                          {GL_FRAGMENT_SHADER, "sunmap_disc.frag", shaders::sunmap_disc_frag}},
                         samples > 1 ? "#define PER_SAMPLE\n" : "");
        if (!disc) return disc.error();
        m_sum = std::move(*sum);
        m_disc = std::move(*disc);
        return Ok{};
    }

    //! Collects the objects that may overlap the sun's cone; false when one surely covers it.
    bool cull(const Scene& view) {
        m_firsts.clear();
        m_counts.clear();
        const Vec3 eye = view.camera.position, s = normalize(view.sun.direction);
        const double alpha = view.sun.angularRadiusDeg * std::numbers::pi / 180.0;
        const double light = view.sun.distance > 0 ? view.sun.distance : 1e300;
        for (const MeshObjectRange& r : m_ranges) {
            const Vec3 toObject = r.centre - eye;
            const double distance = length(toObject);
            if (distance - r.boundRadius >= light) continue;  // wholly behind the light
            if (distance <= r.solidRadius) return false;      // the eye is inside it
            if (distance <= r.boundRadius) {                  // the eye may be inside: draw it
                m_firsts.push_back(r.first), m_counts.push_back(r.count);
                continue;
            }
            const double angle = std::acos(std::clamp(dot(toObject, s) / distance, -1.0, 1.0));
            if (r.solidRadius > 0 && distance + r.solidRadius < light &&
                angle + alpha <= std::asin(r.solidRadius / distance))
                return false;
            if (angle <= alpha + std::asin(r.boundRadius / distance)) {
                m_firsts.push_back(r.first), m_counts.push_back(r.count);
            }
        }
        return true;
    }

    std::string m_variant;
    std::optional<SunMapSum> m_sum;
    bool m_drewMaps = false;  //!< the last measure() drew the maps (no early out)
    gl::Program m_disc, m_black;
    gl::VertexArray m_emptyVao;
    std::vector<MeshObjectRange> m_ranges;
    std::vector<GLint> m_firsts;
    std::vector<GLsizei> m_counts;
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeTextureMaskMethod(const Scene& world,
                                                             const std::string& variant) {
    return TextureMaskMethod::create(world, variant);
}

}  // namespace flarekit::occlusion
