// SPDX-License-Identifier: Apache-2.0
// Per-pass timing of a chain run (`postfx -v`, the benchmarks): the steps of one label are summed.
#pragma once

#include <chrono>
#include <vector>

#include "flarekit/PostFx.h"
#include "postfx/ChainPlan.h"

namespace flarekit::postfx {

class PassClock {
  public:
    explicit PassClock(std::vector<PassTime>* times) : m_times(times) {}
    bool on() const { return m_times != nullptr; }
    //! Runs `work` and, when timing, adds its wall time (CPU).
    template <typename Work>
    void run(const char* pass, Size written, const Work& work) {
        const auto start = std::chrono::steady_clock::now();
        work();
        if (!m_times) return;
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        add(pass, written, ms, ms);
    }
    //! Adds a measurement (the GL chain times its passes itself).
    void add(const char* pass, Size written, double ms, double wallMs) {
        if (!m_times) return;
        for (PassTime& t : *m_times) {
            if (t.pass == pass) {
                t.milliseconds += ms, t.wallMilliseconds += wallMs,
                    t.megapixels += written.megapixels();
                return;
            }
        }
        m_times->push_back({pass, ms, wallMs, written.megapixels()});
    }

  private:
    std::vector<PassTime>* m_times;
};

}  // namespace flarekit::postfx
