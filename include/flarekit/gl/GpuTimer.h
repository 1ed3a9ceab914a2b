// SPDX-License-Identifier: Apache-2.0
// GPU time of a span of GL commands, from two GL_TIMESTAMP queries around it: what the
// benchmarks report as "GPU ms". A GL context must be current; move-only.
#pragma once

namespace flarekit {

class GpuTimer {
  public:
    GpuTimer();
    ~GpuTimer();
    GpuTimer(GpuTimer&& other) noexcept : m_queries{other.m_queries[0], other.m_queries[1]} {
        other.m_queries[0] = other.m_queries[1] = 0;
    }
    GpuTimer& operator=(GpuTimer&& other) noexcept;
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    void begin() const;
    void end() const;
    //! The time between begin() and end(); waits for the GPU to finish those commands.
    double milliseconds() const;

  private:
    unsigned m_queries[2] = {0, 0};
};

}  // namespace flarekit
