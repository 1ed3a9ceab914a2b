// SPDX-License-Identifier: Apache-2.0
// Float compositing of premultiplied linear-light RGBA. Plain loops the compiler vectorises.
#include <array>

#include "flarekit/Blend.h"

namespace flarekit {

std::optional<BlendMode> parseBlendMode(std::string_view name) {
    for (std::size_t i = 0; i < kBlendModeNames.size(); ++i) {
        if (kBlendModeNames[i] == name) return BlendMode(i);
    }
    return std::nullopt;
}

std::string_view blendModeName(BlendMode mode) {
    return kBlendModeNames[std::size_t(mode)];
}

void compositeSpan(BlendMode mode, const float* src, float* dst, std::size_t n) {
    switch (mode) {
        case BlendMode::Add:
            for (std::size_t i = 0; i < n; ++i) {
                dst[4 * i + 0] += src[4 * i + 0];
                dst[4 * i + 1] += src[4 * i + 1];
                dst[4 * i + 2] += src[4 * i + 2];
            }
            break;
        case BlendMode::Screen:
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t c = 0; c < 3; ++c) {
                    const float s = src[4 * i + c], d = dst[4 * i + c];
                    dst[4 * i + c] = s + d - s * d;
                }
                dst[4 * i + 3] = src[4 * i + 3] + dst[4 * i + 3] * (1.f - src[4 * i + 3]);
            }
            break;
        case BlendMode::Over:
            for (std::size_t i = 0; i < n; ++i) {
                const float keep = 1.f - src[4 * i + 3];
                for (std::size_t c = 0; c < 4; ++c)
                    dst[4 * i + c] = src[4 * i + c] + dst[4 * i + c] * keep;
            }
            break;
    }
}

}  // namespace flarekit
