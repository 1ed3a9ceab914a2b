// SPDX-License-Identifier: Apache-2.0
// Ghosts: the seed's LensFlarePS (killzone2-post-process-lens-flare.txt), one loop iteration
// per ghost, plus the falloff and centring that modern engines add. For the output pixel at
// texture coordinate uv:
//   mirror = 1 - uv;  n = (mirror * 2 - 1) * scale            (the seed's vNormalizedCoord)
//   toward = normalize(-n)                                    (vTowardCenter)
//   dist = blur * samples                                     (fBlurDist)
//   sample i at n + toward / sourceSize * dist * offset(i), offset(i) = 1 - 2i (seed)
//   sum += max(0, bloom(p * 0.5 + 0.5) - threshold) * tint, skipping p outside [0, 1]
//   ghost = sum / samples
// so a light at normalised l appears at -l / scale. Two of the seed's quiet edge cases:
// - normalize(0) at the exact screen centre (odd sizes) is NaN in HLSL and GLSL; here the
//   direction is (0, 0) there, so every sample lands on the pixel's own point.
// - the blur offsets divide by g_vSourceDimensions, the *bloom buffer's* size: one step is
//   `dist` bloom texels in the normalised [-1, 1] space, i.e. 2 * blur * samples / size.
//   `sourceTexel` below is that 1 / size, passed in, never the output's size.
// The seed's offsets run from +1 to 1 - 2 (samples - 1) steps: nearly all of the blur lies
// away from the centre. `centered` uses (samples - 1) - 2i instead, the same span about p.
// Three modern additions, each off at the seed's values: each tap is weighed by borderWindow, so
// the mirrored border of the buffer fades instead of cutting (the seed's ghosts draw it as a
// straight-edged slab when a bright sky or lamp touches the frame edge); the tint can be
// desaturated toward its own luminance (ghostTint), so a ghost over a warm lamp stays warm; and
// a magnified ghost is dimmed by the area it spreads over (ghostTint), so a lit window's ghost
// is not a window-bright wash over a quarter of the frame.
// Twin: shaders/ghosts.frag.
#pragma once

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "flarekit/PostFx.h"
#include "postfx/HotTexels.h"
#include "postfx/Kernel.h"

namespace flarekit::postfx {

struct GhostsUniforms {
    Vec2 invOutSize;
    Vec2 sourceTexel;  //!< 1 / bloom size (g_vSourceDimensions)
    std::vector<GhostParams> ghosts;
    float intensity = 1.f;   //!< flareIntensity
    std::vector<Rgb> tints;  //!< ghostTint of each ghost, once per pass (ghostsUniforms)
};

//! Rec. 709 luminance weights: the tint's luminance is what `saturation` keeps.
inline constexpr float kLumaR = 0.2126f, kLumaG = 0.7152f, kLumaB = 0.0722f;

//! The tint the pass multiplies by: the seed's vTint with its colour scaled by `saturation`
//! about its luminance, and dimmed by scale^2 for a magnified ghost when `conserveArea` (computed
//! once per pass, so the shader receives it ready).
inline Rgb ghostTint(const GhostParams& g) {
    const float area = g.conserveArea ? std::min(1.f, g.scale * g.scale) : 1.f;
    if (g.saturation >= 1.f && area >= 1.f) return g.tint;  // the seed's vTint bit for bit
    const float luma = kLumaR * g.tint[0] + kLumaG * g.tint[1] + kLumaB * g.tint[2];
    Rgb tint;
    for (int c = 0; c < 3; ++c) tint[c] = (luma + (g.tint[c] - luma) * g.saturation) * area;
    return tint;
}

//! The pass's uniforms, each ghost's tint resolved once (as the shader receives it).
inline GhostsUniforms ghostsUniforms(Vec2 invOutSize, Vec2 sourceTexel,
                                     const std::vector<GhostParams>& ghosts, float intensity) {
    GhostsUniforms u{invOutSize, sourceTexel, ghosts, intensity, {}};
    for (const GhostParams& g : ghosts) u.tints.push_back(ghostTint(g));
    return u;
}

inline F4 ghostPixel(const GhostParams& g, const Rgb& base, Vec2 sourceTexel, const Tex& bloom,
                     Vec2 uv) {
    const Vec2 n{((1.f - uv.x) * 2.f - 1.f) * g.scale, ((1.f - uv.y) * 2.f - 1.f) * g.scale};
    const float len = std::sqrt(n.x * n.x + n.y * n.y);
    const Vec2 toward = len > 0.f ? Vec2{-n.x / len, -n.y / len} : Vec2{0.f, 0.f};
    const float dist = g.blur * float(g.samples);
    const Vec2 unit{toward.x * sourceTexel.x * dist, toward.y * sourceTexel.y * dist};
    const float first = g.centered ? float(g.samples - 1) : 1.f;
    // The falloff is weighed once, at the unblurred point n: per sample it would cost a pow per
    // tap for a difference the blur hides.
    const float weight = centreFalloff(n, g.falloff);
    const F4 tint{base[0] * weight, base[1] * weight, base[2] * weight, 0.f};
    F4 sum = splat(0.f);
    for (int i = 0; i < g.samples; ++i) {
        const float offset = first - 2.f * float(i);
        const Vec2 p{n.x + unit.x * offset, n.y + unit.y * offset};
        const Vec2 s{p.x * 0.5f + 0.5f, p.y * 0.5f + 0.5f};
        if (s.x >= 0.f && s.x <= 1.f && s.y >= 0.f && s.y <= 1.f) {
            const F4 texel = g.linearFilter ? bilinear(bloom, s) : pointSample(bloom, s);
            sum += max0(texel - g.threshold) * tint * borderWindow(s, g.borderFade);
        }
    }
    return sum / float(g.samples);
}

inline F4 ghostsPixel(const GhostsUniforms& u, const Tex& bloom, int x, int y) {
    const Vec2 uv = pixelUv(x, y, u.invOutSize);
    F4 total = splat(0.f);
    for (std::size_t i = 0; i < u.ghosts.size(); ++i)
        total += ghostPixel(u.ghosts[i], u.tints[i], u.sourceTexel, bloom, uv);
    return rgbOnly(total * u.intensity);
}

//! The pass unit: its pixel over the bloom buffer and its uniforms by ghosts.frag's names (one
//! array element per ghost).
inline F4 passPixel(const GhostsUniforms& u, const Tex* in, int x, int y) {
    return ghostsPixel(u, in[0], x, y);
}

//! The CPU's draw of the pass: ghostsPixel at every pixel, bit for bit (tested), leaving out a
//! ghost at a pixel where none of its taps can read light above its threshold (HotTexels), as
//! such a ghost adds exactly +0 there. Its taps lie within `reach` texels of its unblurred
//! point n on each axis: offsets up to `widest` steps of |unit| <= sourceTexel x blur x samples
//! (toward is a unit vector), halved from [-1, 1] to [0, 1] and scaled to the bloom's texels.
inline void drawPass(const GhostsUniforms& u, const Tex* in, Image& out) {
    const Tex bloom = in[0];
    struct Reach {
        HotTexels hot;
        Vec2 half;
    };
    std::vector<Reach> reaches;
    for (std::size_t i = 0; i < u.ghosts.size(); ++i) {
        const GhostParams& g = u.ghosts[i];
        const float first = g.centered ? float(g.samples - 1) : 1.f;
        const float widest =
            std::max(std::abs(first), std::abs(first - 2.f * float(g.samples - 1)));
        const float steps = 0.5f * std::abs(g.blur * float(g.samples)) * widest;
        const bool sameThreshold = i > 0 && u.ghosts[i - 1].threshold == g.threshold;
        reaches.push_back({sameThreshold ? reaches.back().hot : HotTexels(bloom, g.threshold),
                           {steps * u.sourceTexel.x * float(bloom.width),
                            steps * u.sourceTexel.y * float(bloom.height)}});
    }
    runPass(out, [&](int x, int y) {
        const Vec2 uv = pixelUv(x, y, u.invOutSize);
        F4 total = splat(0.f);
        for (std::size_t i = 0; i < u.ghosts.size(); ++i) {
            const GhostParams& g = u.ghosts[i];
            const Reach& r = reaches[i];
            const Vec2 n{((1.f - uv.x) * 2.f - 1.f) * g.scale,
                         ((1.f - uv.y) * 2.f - 1.f) * g.scale};
            const Vec2 at = texelCoord(bloom, {n.x * 0.5f + 0.5f, n.y * 0.5f + 0.5f});
            if (r.hot.misses({at.x - r.half.x, at.y - r.half.y},
                             {at.x + r.half.x, at.y + r.half.y}))
                continue;
            total += ghostPixel(g, u.tints[i], u.sourceTexel, bloom, uv);
        }
        return rgbOnly(total * u.intensity);
    });
}

template <class Sink>
void bindUniforms(const GhostsUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("sourceTexel", u.sourceTexel),
        s.set("intensity", u.intensity);
    s.set("ghostCount", int(u.ghosts.size()));
    for (std::size_t i = 0; i < u.ghosts.size(); ++i) {
        const GhostParams& g = u.ghosts[i];
        const auto at = [i](const char* array) {
            return std::string(array) + "[" + std::to_string(i) + "]";
        };
        s.set(at("tints").c_str(), u.tints[i]), s.set(at("scales").c_str(), g.scale);
        s.set(at("blurs").c_str(), g.blur), s.set(at("thresholds").c_str(), g.threshold);
        s.set(at("falloffs").c_str(), g.falloff), s.set(at("sampleCounts").c_str(), g.samples);
        s.set(at("centered").c_str(), int(g.centered)),
            s.set(at("useBilinear").c_str(), int(g.linearFilter));
        s.set(at("borderFades").c_str(), g.borderFade);
    }
}

}  // namespace flarekit::postfx
