// SPDX-License-Identifier: Apache-2.0
// Anamorphic streaks: a long horizontal blur of the 1/4-res bright image, built the way
// Kawase (GDC 2003, the seed's source) and Oat ("Real-Time 3D Scene Post-Processing", GDC
// 2003) build streaks: a few passes of 4 taps, pass p spaced 4^p texels apart, tap k weighted
// a^(k 4^p) with a = e^(-falloff / L) per texel (L = half length in texels). Because taps
// 0..3 are the base-4 digits of an offset, P passes together weigh every offset 0 .. 4^P - 1
// exactly once, by a^offset: a smooth exponential tail whose length costs log4(L) passes, not
// L taps. (Taps -3..3 in one chain would count some offsets several times and bead.) One chain
// runs right, one left; the left chain's last pass adds the right chain's result and the
// tint, halving the doubled centre.
// Taps are whole texels (no filtering), so CPU and GL read identical values; samples outside
// the image count as black. Each pass divides by its weight sum, so energy is kept and the
// streak's brightness is set by `intensity`. Twin: shaders/streaks.frag.
#pragma once

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "flarekit/PostFx.h"
#include "postfx/Kernel.h"

namespace flarekit::postfx {

inline constexpr int kStreakTaps = 4;       //!< taps 0..3: base-4 digits (Oat's b = 4)
inline constexpr int kStreakMaxPasses = 8;  //!< 4^8 texels: longer than any image

struct StreakUniforms {
    int step = 1;                              //!< signed texels between taps: +-4^pass
    std::array<float, kStreakTaps> weights{};  //!< normalised, tap 0 .. 3
    float threshold = 0.f;                     //!< subtracted on each chain's first pass only
    bool addOther = false;  //!< the left chain's last pass: + the right chain's result
    F4 outScale = F4{1.f, 1.f, 1.f, 0.f};  //!< tint x intensity / 2 on that last pass
};

struct StreakPlan {
    std::vector<StreakUniforms> right, left;  //!< both empty: streaks off
};

//! The passes for an image `width` texels wide (at the streak resolution).
inline StreakPlan streakPasses(const StreakParams& params, int width, float intensity) {
    const double halfLength = std::max(1.0, double(params.length) * width);
    const double perTexel = std::exp(-double(params.falloff) / halfLength);
    int passes = 1;
    while (passes < kStreakMaxPasses && std::pow(4.0, passes) - 1.0 < halfLength) ++passes;
    StreakPlan plan;
    for (int direction : {1, -1}) {
        std::vector<StreakUniforms>& chain = direction > 0 ? plan.right : plan.left;
        for (int p = 0; p < passes; ++p) {
            StreakUniforms u;
            const int spacing = 1 << (2 * p);
            u.step = direction * spacing;
            double w[kStreakTaps], sum = 0;
            for (int k = 0; k < kStreakTaps; ++k)
                sum += (w[k] = std::pow(perTexel, double(k * spacing)));
            for (int k = 0; k < kStreakTaps; ++k) u.weights[std::size_t(k)] = float(w[k] / sum);
            u.threshold = p == 0 ? params.threshold : 0.f;
            chain.push_back(u);
        }
    }
    StreakUniforms& last = plan.left.back();
    last.addOther = true;
    const float k = 0.5f * intensity;
    last.outScale = F4{params.tint[0] * k, params.tint[1] * k, params.tint[2] * k, 0.f};
    return plan;
}

inline F4 streakPixel(const StreakUniforms& u, const Tex& src, const Tex& other, int x, int y) {
    F4 sum = splat(0.f);
    for (int k = 0; k < kStreakTaps; ++k) {
        const int sx = x + k * u.step;
        if (sx >= 0 && sx < src.width)
            sum += max0(src.texel(sx, y) - u.threshold) * u.weights[std::size_t(k)];
    }
    if (u.addOther) sum += other.texel(x, y);
    return rgbOnly(sum * u.outScale);
}

//! The pass unit: its pixel over (the previous pass, and with addOther the right chain's
//! result) and its uniforms by streaks.frag's names.
inline F4 passPixel(const StreakUniforms& u, const Tex* in, int x, int y) {
    return streakPixel(u, in[0], u.addOther ? in[1] : in[0], x, y);
}
template <class Sink>
void bindUniforms(const StreakUniforms& u, Sink& s) {
    s.set("step", u.step), s.set("threshold", u.threshold), s.set("addOther", int(u.addOther));
    s.set("weights", std::span<const float>(u.weights)), s.set("outScale", u.outScale);
}

}  // namespace flarekit::postfx
