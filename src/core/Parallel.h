// SPDX-License-Identifier: Apache-2.0
// parallelFor and friends: the one place flarekit touches its thread pool (oneTBB), so kernels
// stay plain loops over row ranges.
#pragma once

#include <functional>

namespace flarekit {

//! Calls body(begin, end) on disjoint sub-ranges of [begin, end), in parallel. `grain` is the
//! smallest range worth a task.
void parallelFor(int begin, int end, int grain, const std::function<void(int, int)>& body);

//! Runs fn with every parallelFor inside it on the calling thread alone (a background thread
//! that must not take the pool's workers from the foreground: the demo's frame writer).
void runOnThisThread(const std::function<void()>& fn);

//! Limits worker threads for the lifetime of the returned object (benchmarks: 1 vs 2 cores).
class ThreadLimit {
  public:
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

  private:
    void* m_control;
};

}  // namespace flarekit
