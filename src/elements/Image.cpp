// SPDX-License-Identifier: Apache-2.0
// Image elements: an engine's flare texture drawn as the element. The texture spans the
// element's diameter (local [-1, 1] on both axes, stretched by its aspect), as Unity's,
// Babylon's and three.js's flare quads do; texels are premultiplied by their alpha, as those
// engines' additive flare shaders multiply colour by alpha or by an opaque texture's 1.
#include <algorithm>
#include <cmath>

#include "elements/ElementKernel.h"

namespace flarekit {

Rgba shadeImage(const ElementKernel& k, float x, float y) {
    const Image* tex = k.params.textureImage.get();
    if (!tex || tex->width() < 1 || tex->height() < 1) return {};
    if (std::abs(x) >= 1.f + k.pixel || std::abs(y) >= 1.f + k.pixel) return {};
    // Texel centres at (i + 0.5) / width over [-1, 1]; clear past the border (one texel fades).
    const float fx = (x + 1.f) * 0.5f * float(tex->width()) - 0.5f;
    const float fy = (y + 1.f) * 0.5f * float(tex->height()) - 0.5f;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float wx = fx - float(x0), wy = fy - float(y0);
    Rgba sum{};
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const int tx = x0 + i, ty = y0 + j;
            if (tx < 0 || ty < 0 || tx >= tex->width() || ty >= tex->height()) continue;
            const float w = (i ? wx : 1.f - wx) * (j ? wy : 1.f - wy);
            const Rgba& t = tex->at(tx, ty);
            const float a = std::clamp(t.a, 0.f, 1.f);
            sum.r += w * t.r * a * k.outer[0];
            sum.g += w * t.g * a * k.outer[1];
            sum.b += w * t.b * a * k.outer[2];
            sum.a += w * a;
        }
    }
    sum.a = std::min(sum.a, 1.f);
    return sum;
}

}  // namespace flarekit
