// SPDX-License-Identifier: Apache-2.0
// Figures 7 and 8 of Tanczos 1999 as span loops. This file is compiled with auto-vectorisation
// off (see src/CMakeLists.txt) so the benchmark compares the article's scalar code with the
// SIMD version honestly, instead of with what the compiler made of it.
#include <array>

#include "flarekit/Blend.h"

namespace flarekit::blend8 {

const std::uint8_t* addLut() {
    // Figure 8: for (i = 0; i < 512; i++) alut[i] = i > 255 ? 255 : i;
    static const std::array<std::uint8_t, 512> table = [] {
        std::array<std::uint8_t, 512> t{};
        for (int i = 0; i < 512; ++i) t[std::size_t(i)] = std::uint8_t(i > 255 ? 255 : i);
        return t;
    }();
    return table.data();
}

void addSpanScalar16(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                     std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out[i] = add(a[i], b[i]);
}

void addSpanLut(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out, std::size_t n) {
    const std::uint8_t* alut = addLut();
    for (std::size_t i = 0; i < n; ++i) out[i] = alut[a[i] + b[i]];  // Figure 9
}

}  // namespace flarekit::blend8
