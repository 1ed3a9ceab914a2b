// SPDX-License-Identifier: Apache-2.0
#include "core/Parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace flarekit {

void parallelFor(int begin, int end, int grain, const std::function<void(int, int)>& body) {
    if (end <= begin) return;
    if (end - begin <= grain) {
        body(begin, end);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<int>(begin, end, std::size_t(grain > 0 ? grain : 1)),
                      [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

void runOnThisThread(const std::function<void()>& fn) {
    // An arena of one slot, reserved for its caller: its tasks have no other thread to run on.
    tbb::task_arena alone(1, 1);
    alone.execute(fn);
}

ThreadLimit::ThreadLimit(int threads)
    : m_control(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                        std::size_t(threads > 0 ? threads : 1))) {}

ThreadLimit::~ThreadLimit() {
    delete static_cast<tbb::global_control*>(m_control);
}

}  // namespace flarekit
