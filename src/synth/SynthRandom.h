// SPDX-License-Identifier: Apache-2.0
// The generator's random numbers: a counter-based stream per sample (SplitMix64, Steele, Lea
// and Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014), so sample i of
// seed S draws the same numbers on any machine, in any order, on any thread, and the standard
// library's distributions (whose algorithms differ between implementations) are not used.
#pragma once

#include <cmath>
#include <cstdint>

namespace flarekit::synth_detail {

inline std::uint64_t splitMix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class SampleRandom {
  public:
    //! The stream of sample `index` of `seed`, `stream` keeping independent uses apart.
    SampleRandom(std::uint64_t seed, std::uint64_t index, std::uint64_t stream = 0)
        : m_state(splitMix(splitMix(seed) ^ splitMix(index + 0x632BE59BD9B4E019ull) ^
                           (stream * 0xD1B54A32D192ED03ull))) {}
    std::uint64_t next() { return splitMix(m_state += 0x9E3779B97F4A7C15ull); }
    //! Uniform in [0, 1), 53 bits.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    double logRange(double lo, double hi) { return std::exp(range(std::log(lo), std::log(hi))); }
    //! An integer in [lo, hi].
    int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }
    bool chance(double p) { return uniform() < p; }
    //! A standard normal (Box-Muller).
    double normal() {
        const double u = 1.0 - uniform(), v = uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
    }

  private:
    std::uint64_t m_state;
};

}  // namespace flarekit::synth_detail
