// SPDX-License-Identifier: Apache-2.0
// Per-type element defaults: what each element type looks like with no keys set.
#include "flarekit/Elements.h"

namespace flarekit {

ElementParams defaultElement(ElementType type) {
    ElementParams p;
    p.type = type;
    switch (type) {
        case ElementType::Glow:  // Tanczos 1999: "a gradient from a bright color to a darker color"
            p.size = 0.3f;
            p.color = {1.f, 0.8f, 0.55f};
            p.innerColor = Rgb{1.f, 1.f, 1.f};
            break;
        case ElementType::Ring:  // Tanczos 1999: "an antialiased circle of some dark color"
            p.size = 0.12f;
            p.color = {0.35f, 0.45f, 0.8f};
            p.intensity = 0.35f;
            break;
        case ElementType::Streaks:  // Tanczos 1999: "Bright white colors usually work best"
            p.size = 0.5f;
            p.count = 4;
            p.thickness = 0.008f;
            break;
        case ElementType::Rays:
            p.size = 0.35f;
            p.count = 96;
            p.thickness = 0.004f;
            p.falloff = 1.5f;
            p.intensity = 0.5f;
            break;
        case ElementType::Disc:  // Tanczos 1999, Figure 11: purple outer ring to a black centre
            p.size = 0.06f;
            p.color = {0.45f, 0.25f, 0.7f};
            p.innerColor = Rgb{0.f, 0.f, 0.f};
            p.softness = 0.15f;
            p.intensity = 0.4f;
            break;
        case ElementType::EdgeStreak:  // a long thin smear along the border
            p.size = 0.3f;
            p.aspect = 8.f;
            p.color = {1.f, 0.75f, 0.5f};
            p.innerColor = Rgb{1.f, 1.f, 1.f};
            p.intensity = 0.5f;
            break;
        case ElementType::Image:  // the texture as drawn, white tint
            p.size = 0.1f;
            break;
        case ElementType::Polygon:
            p.size = 0.07f;
            p.color = {0.4f, 0.6f, 0.5f};
            p.softness = 0.1f;
            p.intensity = 0.2f;
            break;
    }
    return p;
}

}  // namespace flarekit
