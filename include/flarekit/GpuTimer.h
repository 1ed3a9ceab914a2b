// GPU time of a span of GL commands, from a GL_TIME_ELAPSED query: what the benchmarks report
// as "GPU ms". A GL context must be current; move-only.
#pragma once

namespace flarekit {

class GpuTimer {
  public:
    GpuTimer();
    ~GpuTimer();
    GpuTimer(GpuTimer&& other) noexcept : m_query(other.m_query) { other.m_query = 0; }
    GpuTimer& operator=(GpuTimer&& other) noexcept;
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    void begin() const;
    void end() const;
    //! The time between begin() and end(); waits for the GPU to finish those commands.
    double milliseconds() const;

  private:
    unsigned m_query = 0;
};

}  // namespace flarekit
