// SPDX-License-Identifier: Apache-2.0
#include "GlViewBackends.h"

#include <chrono>
#include <optional>

#include "core/Parallel.h"
#include "flarekit/PostFx.h"
#include "flarekit/gl/GpuLens.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::studio {

Result<std::shared_ptr<GlViewThread>> GlViewThread::start() {
    std::shared_ptr<GlViewThread> t(new GlViewThread());
    std::promise<Status> started;
    auto ready = started.get_future();
    t->m_thread = std::thread([raw = t.get(), &started] { raw->loop(started); });
    if (Status s = ready.get(); !s) {
        t->m_thread.join();
        return s.error();
    }
    return t;
}

GlViewThread::~GlViewThread() {
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void GlViewThread::post(std::function<void()> work) {
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(std::move(work));
    }
    m_wake.notify_all();
}

void GlViewThread::loop(std::promise<Status>& started) {
    // The CPU halves of the jobs (light finding, conversions) stay on this thread's cores.
    runOnThisThread([&] {
        auto context = gl::createQuietHeadlessGl();
        if (!context) {
            started.set_value(context.error());
            return;
        }
        m_software = (*context)->software();
        started.set_value(Ok{});
        for (;;) {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || !m_queue.empty(); });
            if (m_queue.empty()) return;  // stopped, nothing left
            std::function<void()> work = std::move(m_queue.front());
            m_queue.pop_front();
            lock.unlock();
            work();
        }
    });
}

namespace {

class PostFxOnThread final : public PostFxBackend {
  public:
    explicit PostFxOnThread(std::shared_ptr<GlViewThread> thread) : m_thread(std::move(thread)) {}
    ~PostFxOnThread() override {
        m_thread->run([this] { m_chain.reset(); });  // its GL objects, in their context
    }
    PostFxOnThread(const PostFxOnThread&) = delete;
    PostFxOnThread& operator=(const PostFxOnThread&) = delete;
    std::string name() const override { return "gl"; }
    bool usesGl() const override { return true; }
    Result<PostFxResult> run(Image& image, bool, const PostFxParams& params,
                             const PostFxOptions& options, int repeat, double& warmSeconds,
                             const std::string& in, const JobEvents&) const override {
        warmSeconds = 0;
        return m_thread->run([&]() -> Result<PostFxResult> {
            if (Status s = gl::checkGlFrame(image.width(), image.height(), 1, in + ": image"); !s)
                return s.error();
            if (!m_chain) {  // made on the GL thread, used there only
                auto chain = GpuPostFx::create();
                if (!chain) return chain.error();
                m_chain.emplace(std::move(*chain));
            }
            // As the CLI's backend: halves only where the GPU is not this CPU.
            PostFxOptions o = options;
            if (m_thread->software()) o.halfInput = o.halfReadback = false;
            Result<PostFxResult> out = internalError("postfx: no run");
            for (int i = 0; i < std::max(1, repeat); ++i) out = m_chain->run(image, params, o);
            return out;
        });
    }

  private:
    std::shared_ptr<GlViewThread> m_thread;
    mutable std::optional<GpuPostFx> m_chain;  //!< touched on m_thread only
};

class LensOnThread final : public LensBackend {
  public:
    explicit LensOnThread(std::shared_ptr<GlViewThread> thread) : m_thread(std::move(thread)) {}
    std::string name() const override { return "gl"; }
    bool usesGl() const override { return true; }
    Result<LensFlareLayers> render(const Lens& lens, int width, int height,
                                   const std::vector<LensLight>& lights,
                                   const LensRenderOptions& options, const std::string& in, bool,
                                   const JobEvents&) const override {
        return m_thread->run([&]() -> Result<LensFlareLayers> {
            if (Status s = gl::checkGlFrame(width, height, 1, in + ": image"); !s) return s.error();
            return renderLensFlareGl(lens, width, height, lights, options);
        });
    }

  private:
    std::shared_ptr<GlViewThread> m_thread;
};

}  // namespace

std::shared_ptr<const PostFxBackend> glViewPostFxBackend(std::shared_ptr<GlViewThread> thread) {
    return std::make_shared<const PostFxOnThread>(std::move(thread));
}

std::shared_ptr<const LensBackend> glViewLensBackend(std::shared_ptr<GlViewThread> thread) {
    return std::make_shared<const LensOnThread>(std::move(thread));
}

}  // namespace flarekit::studio
