// SPDX-License-Identifier: Apache-2.0
// `query`: occlusion queries. The disc is drawn at the far plane twice over the frame's depth
// (no colour writes): once with the depth test (GL_SAMPLES_PASSED counts the sky pixels under
// the disc) and once without (counts all of the disc's pixels on screen). Coverage is their
// ratio. Results are collected when GL_QUERY_RESULT_AVAILABLE says so, normally the next frame,
// so the CPU never waits. Pixels count whole (centre inside the disc), unweighted. With a
// multisampled frame the disc is drawn against the multisampled depth, where GL_SAMPLES_PASSED
// counts samples, so a pixel half covered by an occluder counts half.
#include <vector>

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"
#include "scene/SceneTargets.h"

namespace flarekit::occlusion {

namespace {
constexpr int kRing = 3;  //!< query pairs in flight

class QueryMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create() {
        auto program =
            linkWithDisc({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                          {GL_FRAGMENT_SHADER, "disc_at_far.frag", shaders::disc_at_far_frag}});
        if (!program) return program.error();
        return std::unique_ptr<GpuVisibility>(new QueryMethod(std::move(*program)));
    }
    std::string name() const override { return "query"; }
    int latencyFrames() const override { return m_latency; }
    int resultAge() const override { return int(m_frame - m_resultFrame); }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        ++m_frame;
        // This frame's pair holds the oldest frame in flight: with a full ring it must finish
        // (wait) and be published before the newer ones collect() finds done.
        Pair& p = m_pairs[std::size_t(m_frame % kRing)];
        if (p.pending) collectPair(p, true);
        collect();
        const SunDiscView v = sunDiscView(view);
        p.frame = m_frame;
        if (v.empty()) {
            // No disc on screen: 0 is known now, published in frame order with the queries in
            // flight so an older result never overwrites it.
            p.pending = true;
            p.knownEmpty = true;
            m_lastVisible = m_offScreen.get();  // no samples: gated drawing is skipped
            return Ok{};
        }
        setSunDiscUniforms(m_program.get(), v);
        glBindFramebuffer(GL_FRAMEBUFFER, targetFor(renderer));
        glViewport(0, 0, v.width, v.height);
        glEnable(GL_SCISSOR_TEST);
        glScissor(v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glBindVertexArray(m_vao.get());
        glUseProgram(m_program.get());
        glDepthFunc(GL_LEQUAL);  // sky depth is the cleared 1.0
        glBeginQuery(GL_SAMPLES_PASSED, p.visible.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEndQuery(GL_SAMPLES_PASSED);
        glDepthFunc(GL_ALWAYS);
        glBeginQuery(GL_SAMPLES_PASSED, p.total.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEndQuery(GL_SAMPLES_PASSED);
        glDepthFunc(GL_LESS);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        p.pending = true;
        m_lastVisible = p.visible.get();
        glFlush();
        return gl::checkError("query: disc draws");
    }

    unsigned conditionalRenderQuery() const override { return m_lastVisible; }

    std::optional<double> latestCoverage() override {
        collect();
        return GpuMethod::latestCoverage();
    }

  private:
    struct Pair {
        gl::Query visible, total;
        bool pending = false;
        bool knownEmpty = false;  //!< the disc was off screen: coverage 0, nothing queried
        long frame = 0;
    };
    explicit QueryMethod(gl::Program program) : m_program(std::move(program)) {
        for (Pair& p : m_pairs) {
            GLuint q[2];
            glCreateQueries(GL_SAMPLES_PASSED, 2, q);
            p.visible = gl::Query(q[0]);
            p.total = gl::Query(q[1]);
        }
        m_vao = gl::makeVertexArray();
        GLuint empty = 0;
        glCreateQueries(GL_SAMPLES_PASSED, 1, &empty);
        m_offScreen = gl::Query(empty);
        glBeginQuery(GL_SAMPLES_PASSED, empty);  // around nothing: 0 samples
        glEndQuery(GL_SAMPLES_PASSED);
    }
    //! The frame's framebuffer, or with MSAA one holding its multisampled depth (no colour).
    GLuint targetFor(const SceneRenderer& renderer) {
        if (renderer.msaaSamples() <= 1) return sceneTargets(renderer).framebuffer;
        if (!m_msaaTarget) {
            GLuint fb = 0;
            glCreateFramebuffers(1, &fb);
            m_msaaTarget = gl::Framebuffer(fb);
            glNamedFramebufferDrawBuffer(fb, GL_NONE);
            glNamedFramebufferReadBuffer(fb, GL_NONE);
        }
        if (m_msaaDepth != sceneTargets(renderer).multisampleDepth) {
            m_msaaDepth = sceneTargets(renderer).multisampleDepth;
            glNamedFramebufferTexture(m_msaaTarget.get(), GL_DEPTH_ATTACHMENT, m_msaaDepth, 0);
        }
        return m_msaaTarget.get();
    }
    void collect() {
        for (long f = m_frame - kRing + 1; f <= m_frame; ++f) {
            if (f < 1) continue;
            Pair& p = m_pairs[std::size_t(f % kRing)];
            if (p.pending && p.frame == f) collectPair(p, false);
        }
    }
    void collectPair(Pair& p, bool wait) {
        if (p.knownEmpty) {
            p.pending = p.knownEmpty = false;
            publish(0.0);
            m_latency = int(m_frame - p.frame);
            m_resultFrame = p.frame;
            return;
        }
        GLuint ready = 0;
        if (!wait) {
            glGetQueryObjectuiv(p.total.get(), GL_QUERY_RESULT_AVAILABLE, &ready);
            if (!ready) return;
            glGetQueryObjectuiv(p.visible.get(), GL_QUERY_RESULT_AVAILABLE, &ready);
            if (!ready) return;
        }
        GLuint64 visible = 0, total = 0;
        glGetQueryObjectui64v(p.visible.get(), GL_QUERY_RESULT, &visible);
        glGetQueryObjectui64v(p.total.get(), GL_QUERY_RESULT, &total);
        p.pending = false;
        publish(total ? double(visible) / double(total) : 0.0);
        m_latency = int(m_frame - p.frame);
        m_resultFrame = p.frame;
    }

    gl::Program m_program;
    gl::VertexArray m_vao;
    gl::Framebuffer m_msaaTarget;
    GLuint m_msaaDepth = 0;
    GLuint m_lastVisible = 0;
    gl::Query m_offScreen;  //!< a query that counted nothing, for frames with no disc on screen
    Pair m_pairs[kRing];
    long m_frame = 0;
    int m_latency = 0;
    long m_resultFrame = 0;  //!< the frame whose result is the newest
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makeQueryMethod() {
    return QueryMethod::create();
}

}  // namespace flarekit::occlusion
