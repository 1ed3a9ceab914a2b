// SPDX-License-Identifier: Apache-2.0
// SplitMix64 (Steele, Lea, Flood 2014): a tiny generator with a fixed, specified output, so
// seeded elements are identical on every platform and standard library (unlike
// std::uniform_real_distribution, whose algorithm is implementation-defined).
#pragma once

#include <cstdint>

namespace flarekit {

class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    //! Uniform in [0, 1): the top 24 bits, exactly representable in a float.
    float nextFloat() { return float(next() >> 40) * 0x1.0p-24f; }
    //! Uniform in [0, 1): the top 53 bits, exactly representable in a double.
    double nextDouble() { return double(next() >> 11) * 0x1.0p-53; }

  private:
    std::uint64_t m_state;
};

}  // namespace flarekit
