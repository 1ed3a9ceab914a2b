// SPDX-License-Identifier: Apache-2.0
// `pbo`: the lock method without the lock. The depth under the disc is copied into one of a
// ring of pixel buffer objects (the copy runs on the GPU's timeline), a fence marks it, and a
// later frame maps the buffer once its fence has signalled, so the CPU never waits; the result
// arrives one or more frames late (latencyFrames() reports how many it took). With a
// multisampled frame the copy is of the per-pixel sky fraction (SkyFraction), as in readback.
#include <vector>

#include "occlusion/GpuMethod.h"
#include "occlusion/SkyFraction.h"
#include "occlusion/readback/DepthCoverage.h"
#include "scene/SceneTargets.h"

namespace flarekit::occlusion {

namespace {
class PboMethod final : public GpuMethod {
  public:
    static Result<std::unique_ptr<GpuVisibility>> create(int ring) {
        auto sky = SkyFraction::create();
        if (!sky) return sky.error();
        return std::unique_ptr<GpuVisibility>(new PboMethod(ring, std::move(*sky)));
    }
    PboMethod(int ring, SkyFraction sky) : m_sky(std::move(sky)), m_slots(std::size_t(ring)) {
        for (Slot& s : m_slots) {
            GLuint b = 0;
            glCreateBuffers(1, &b);
            s.buffer = gl::Buffer(b);
        }
    }
    ~PboMethod() override {
        for (Slot& s : m_slots)
            if (s.fence) glDeleteSync(s.fence);
    }
    std::string name() const override { return "pbo"; }
    int latencyFrames() const override { return m_latency; }
    int resultAge() const override { return int(m_frame - m_resultFrame); }

    Status measure(const Scene& view, const SceneRenderer& renderer) override {
        ++m_frame;
        // This frame's slot holds the oldest frame in flight: with a full ring it must finish
        // (wait) and be published before the newer ones collect() finds done.
        Slot& slot = m_slots[std::size_t(m_frame % long(m_slots.size()))];
        collectFrame(slot, slot.frame, true);
        collect(false);
        slot.view = sunDiscView(view);
        slot.frame = m_frame;
        if (slot.view.empty()) {
            // No disc on screen: the answer (0) is known now, but it is published in frame order
            // with the reads still in flight, so an older result never overwrites it.
            slot.knownEmpty = true;
            return Ok{};
        }
        const int w = slot.view.x1 - slot.view.x0, h = slot.view.y1 - slot.view.y0;
        const GLsizeiptr bytes = GLsizeiptr(w) * h * GLsizeiptr(sizeof(float));
        if (bytes > slot.capacity) {
            glNamedBufferData(slot.buffer.get(), bytes, nullptr, GL_STREAM_READ);
            slot.capacity = bytes;
        }
        slot.skyFraction = renderer.msaaSamples() > 1;
        GLuint source = sceneTargets(renderer).framebuffer;
        if (slot.skyFraction) {
            auto sky = m_sky.update(slot.view, renderer);
            if (!sky) return sky.error();
            source = *sky;
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.get());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(slot.view.x0, slot.view.y0, w, h,
                     slot.skyFraction ? GL_RED : GL_DEPTH_COMPONENT, GL_FLOAT,
                     nullptr);  // async
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        glFlush();  // so the fence can signal without anyone waiting on it
        return gl::checkError("pbo: glReadPixels into a buffer");
    }

    std::optional<double> latestCoverage() override {
        collect(false);
        return GpuMethod::latestCoverage();
    }

  private:
    struct Slot {
        gl::Buffer buffer;
        GLsizeiptr capacity = 0;
        GLsync fence = nullptr;
        bool knownEmpty = false;   //!< the disc was off screen: coverage 0 without a read
        bool skyFraction = false;  //!< holds sky fractions (MSAA frame), not depth
        SunDiscView view;
        long frame = 0;
    };

    void collect(bool wait) {
        // Oldest first, so the newest finished result is published last.
        for (long f = m_frame - long(m_slots.size()) + 1; f <= m_frame; ++f) {
            if (f < 1) continue;
            Slot& s = m_slots[std::size_t(f % long(m_slots.size()))];
            collectFrame(s, f, wait);
        }
    }

    void collectFrame(Slot& s, long frame, bool wait) {
        if (s.frame != frame) return;
        if (s.knownEmpty) {
            s.knownEmpty = false;
            publish(0.0);
            m_latency = int(m_frame - s.frame);
            m_resultFrame = s.frame;
        } else if (s.fence) {
            collectSlot(s, wait);
        }
    }

    void collectSlot(Slot& s, bool wait) {
        const GLenum state = glClientWaitSync(s.fence, 0, wait ? GLuint64(10'000'000'000) : 0);
        if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return;
        glDeleteSync(s.fence);
        s.fence = nullptr;
        const int w = s.view.x1 - s.view.x0, h = s.view.y1 - s.view.y0;
        const auto* depth = static_cast<const float*>(glMapNamedBufferRange(
            s.buffer.get(), 0, GLsizeiptr(w) * h * GLsizeiptr(sizeof(float)), GL_MAP_READ_BIT));
        if (!depth) return;
        const double coverage =
            s.skyFraction ? coverageFromSkyFraction(s.view, depth, s.view.x0, s.view.y0, w, h)
                          : coverageFromDepth(s.view, depth, s.view.x0, s.view.y0, w, h);
        glUnmapNamedBuffer(s.buffer.get());
        publish(coverage);
        m_latency = int(m_frame - s.frame);
        m_resultFrame = s.frame;
    }

    SkyFraction m_sky;
    std::vector<Slot> m_slots;
    long m_frame = 0;
    int m_latency = 0;
    long m_resultFrame = 0;  //!< the frame whose result is the newest
};
}  // namespace

Result<std::unique_ptr<GpuVisibility>> makePboMethod(int ring) {
    return PboMethod::create(ring);
}

}  // namespace flarekit::occlusion
