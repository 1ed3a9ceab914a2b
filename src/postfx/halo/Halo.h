// SPDX-License-Identifier: Apache-2.0
// Halo: John Chapman's pseudo lens flare halo ("Pseudo Lens Flare", 2013), made aspect-correct.
// In aspect space (x scaled by width / height, so a circle stays a circle) the pixel's mirrored
// position m = -q samples the bloom buffer at m - normalize(m) * r for radii r across
// [radius - thickness/2, radius + thickness/2]. A light at the centre lights the full ring
// |q| = radius; a light at l lights an arc of radius `radius + |l|` on the far side, which is
// how real lens halos swing with the light. Samples outside the image are skipped, as the
// seed's ghosts do, and those near its border weighed down by borderWindow, as the ghosts' are.
// Twin: shaders/halo.frag.
#pragma once

#include "flarekit/PostFx.h"
#include "postfx/ghosts/Ghosts.h"

namespace flarekit::postfx {

//! Radial samples across the ring's thickness: enough that a 0.1-thick ring shows no steps
//! on a blurred bloom buffer.
inline constexpr int kHaloSamples = 8;

struct HaloUniforms {
    Vec2 invOutSize;
    float aspect = 1.f;  //!< width / height
    HaloParams halo;
    float intensity = 1.f;  //!< flareIntensity x halo.intensity
};

inline F4 haloPixel(const HaloUniforms& u, const Tex& bloom, int x, int y) {
    const Vec2 uv = pixelUv(x, y, u.invOutSize);
    const Vec2 m{(1.f - 2.f * uv.x) * u.aspect, 1.f - 2.f * uv.y};  // mirrored, aspect space
    const float len = std::sqrt(m.x * m.x + m.y * m.y);
    const Vec2 dir = len > 0.f ? Vec2{m.x / len, m.y / len} : Vec2{0.f, 0.f};
    // Weighed once, at the mid-radius point (a pow per sample would cost more than the taps).
    const float weight = centreFalloff(
        {(m.x - dir.x * u.halo.radius) / u.aspect, m.y - dir.y * u.halo.radius}, u.halo.falloff);
    const F4 tint{u.halo.tint[0] * weight, u.halo.tint[1] * weight, u.halo.tint[2] * weight, 0.f};
    F4 sum = splat(0.f);
    for (int i = 0; i < kHaloSamples; ++i) {
        const float r =
            u.halo.radius + u.halo.thickness * ((float(i) + 0.5f) / float(kHaloSamples) - 0.5f);
        const Vec2 p{(m.x - dir.x * r) / u.aspect, m.y - dir.y * r};  // back to [-1, 1]
        const Vec2 s{p.x * 0.5f + 0.5f, p.y * 0.5f + 0.5f};
        if (s.x >= 0.f && s.x <= 1.f && s.y >= 0.f && s.y <= 1.f) {
            sum += max0(bilinear(bloom, s) - u.halo.threshold) * borderWindow(s, u.halo.borderFade);
        }
    }
    return rgbOnly(sum * tint * (u.intensity / float(kHaloSamples)));
}

//! The pass unit: its pixel over the bloom buffer and its uniforms by halo.frag's names.
inline F4 passPixel(const HaloUniforms& u, const Tex* in, int x, int y) {
    return haloPixel(u, in[0], x, y);
}
//! The CPU's draw of the pass: haloPixel at every pixel, bit for bit (tested), writing its
//! no-light value where none of the pixel's taps can read light above the threshold
//! (HotTexels). The taps lie on the segment between the first and the last radius along dir.
inline void drawPass(const HaloUniforms& u, const Tex* in, Image& out) {
    const Tex bloom = in[0];
    const HotTexels hot(bloom, u.halo.threshold);
    const auto radiusOf = [&u](int i) {
        return u.halo.radius + u.halo.thickness * ((float(i) + 0.5f) / float(kHaloSamples) - 0.5f);
    };
    const float inner = radiusOf(0), outer = radiusOf(kHaloSamples - 1);
    // haloPixel's value with nothing summed: 0 x tint x scale, with the signs its product has
    // (the falloff weight it leaves out is never negative).
    const Rgb& t = u.halo.tint;
    const F4 dark =
        rgbOnly(splat(0.f) * F4{t[0], t[1], t[2], 0.f} * (u.intensity / float(kHaloSamples)));
    runPass(out, [&](int x, int y) {
        const Vec2 uv = pixelUv(x, y, u.invOutSize);
        const Vec2 m{(1.f - 2.f * uv.x) * u.aspect, 1.f - 2.f * uv.y};
        const float len = std::sqrt(m.x * m.x + m.y * m.y);
        const Vec2 dir = len > 0.f ? Vec2{m.x / len, m.y / len} : Vec2{0.f, 0.f};
        const auto tap = [&](float r) {
            const Vec2 p{(m.x - dir.x * r) / u.aspect, m.y - dir.y * r};
            return texelCoord(bloom, {p.x * 0.5f + 0.5f, p.y * 0.5f + 0.5f});
        };
        const Vec2 a = tap(inner), b = tap(outer);
        const bool misses = hot.misses({std::min(a.x, b.x), std::min(a.y, b.y)},
                                       {std::max(a.x, b.x), std::max(a.y, b.y)});
        return misses ? dark : haloPixel(u, bloom, x, y);
    });
}

template <class Sink>
void bindUniforms(const HaloUniforms& u, Sink& s) {
    s.set("invOutSize", u.invOutSize), s.set("aspect", u.aspect), s.set("radius", u.halo.radius);
    s.set("thickness", u.halo.thickness), s.set("threshold", u.halo.threshold),
        s.set("falloff", u.halo.falloff);
    s.set("intensity", u.intensity), s.set("tint", u.halo.tint);
    s.set("borderFade", u.halo.borderFade);
}

}  // namespace flarekit::postfx
