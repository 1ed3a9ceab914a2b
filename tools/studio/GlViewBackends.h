// SPDX-License-Identifier: Apache-2.0
// The view setting `backend gl`: the post-process chain and the lens's ghosts of the view and
// the export drawn by flarekit's OpenGL backend (GpuPostFx, renderLensFlareGl: what `postfx
// --backend gl` and `lens render --backend gl` run), on one thread of the studio's own with a
// headless context made once. The CLI's backends make a context per image (and compile the
// chain's shaders with it); a view that updates while the light moves cannot pay that each
// time. The thread also keeps the window's context the only one current on the UI thread.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

#include "flarekit/Result.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PostFxJob.h"

namespace flarekit::studio {

class GlViewThread {
  public:
    //! Starts the thread and makes its context; an error (no GL) comes back here.
    static Result<std::shared_ptr<GlViewThread>> start();
    ~GlViewThread();  //!< finishes the work queued, then releases the context
    GlViewThread(const GlViewThread&) = delete;
    GlViewThread& operator=(const GlViewThread&) = delete;

    //! Runs `work` on the GL thread (its context current) and waits for it.
    template <class Work>
    auto run(Work work) -> decltype(work()) {
        std::packaged_task<decltype(work())()> task(std::move(work));
        auto done = task.get_future();
        post([&task] { task(); });
        return done.get();
    }
    bool software() const { return m_software; }  //!< llvmpipe or softpipe: floats, no halves

  private:
    GlViewThread() = default;
    void post(std::function<void()> work);
    void loop(std::promise<Status>& started);

    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<std::function<void()>> m_queue;  //!< guarded by m_mutex
    bool m_stop = false;                        //!< guarded by m_mutex
    bool m_software = false;
    std::thread m_thread;
};

//! The postfx job's backend on `thread`: one GpuPostFx chain kept between calls.
std::shared_ptr<const PostFxBackend> glViewPostFxBackend(std::shared_ptr<GlViewThread> thread);
//! The lens job's backend on `thread`.
std::shared_ptr<const LensBackend> glViewLensBackend(std::shared_ptr<GlViewThread> thread);

}  // namespace flarekit::studio
