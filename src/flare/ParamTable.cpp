#include "flare/ParamTable.h"

#include <array>

namespace flarekit {

namespace {

constexpr std::uint32_t kGlow = typeBit(ElementType::Glow), kRing = typeBit(ElementType::Ring),
                        kStreaks = typeBit(ElementType::Streaks), kRays = typeBit(ElementType::Rays),
                        kDisc = typeBit(ElementType::Disc), kPolygon = typeBit(ElementType::Polygon);
constexpr std::uint32_t kSpikes = kStreaks | kRays;

// Ranges are what still gives a sensible image; they exist to catch typos ("size": 40).
// size [0, 4]: issue 3's example message; 4 image heights covers the widest anamorphic streak.
// colour components [0, 64]: HDR colours above display white, up to a sun-like 64.
const std::array<FieldSpec, 16> kFields = {{
    {"t", FieldKind::Number, -8, 8, kAllTypes, &ElementParams::t, "",
     "position on the flare vector: 1 at the light, 0 at the screen centre, -1 mirrored through it"},
    {"size", FieldKind::Number, 0, 4, kAllTypes, &ElementParams::size, "image heights", "radius"},
    {"color", FieldKind::Color, 0, 64, kAllTypes, &ElementParams::color, "linear RGB",
     "colour; the rim colour where the element has a gradient"},
    {"inner_color", FieldKind::OptionalColor, 0, 64, kGlow | kRing | kDisc | kPolygon | kSpikes,
     &ElementParams::innerColor, "linear RGB",
     "colour at the centre (ring: at its inner edge), blending linearly to `color`; default `color`"},
    {"intensity", FieldKind::Number, 0, 1000, kAllTypes, &ElementParams::intensity, "", "multiplies the colour"},
    {"aspect", FieldKind::Number, 0.05, 20, kAllTypes, &ElementParams::aspect, "",
     "horizontal stretch (2: twice as wide as tall)"},
    {"rotation", FieldKind::Number, -360, 360, kAllTypes, &ElementParams::rotationDeg, "degrees",
     "rotation, clockwise on screen"},
    {"width", FieldKind::Number, 0.001, 1, kRing, &ElementParams::width, "radius", "ring width"},
    {"softness", FieldKind::Number, 0, 1, kRing | kDisc | kPolygon, &ElementParams::softness, "radius",
     "edge blur width (0: one-pixel antialiasing only)"},
    {"count", FieldKind::Integer, 1, 4096, kSpikes, &ElementParams::count, "", "number of streaks or rays"},
    {"thickness", FieldKind::Number, 0.0005, 0.5, kSpikes, &ElementParams::thickness, "radius",
     "width of each streak or ray"},
    {"falloff", FieldKind::Number, 0, 16, kSpikes, &ElementParams::falloff, "",
     "brightness along a spike: (1 - distance/length)^falloff"},
    {"min_length", FieldKind::Number, 0, 1, kRays, &ElementParams::minLength, "radius",
     "shortest ray; lengths are uniform in [min_length, 1]"},
    {"blades", FieldKind::Integer, 3, 32, kPolygon, &ElementParams::blades, "", "aperture blades (polygon sides)"},
    {"seed", FieldKind::Seed, 0, 4294967295.0, kRays, &ElementParams::seed, "",
     "random seed of the rays (same seed, same rays everywhere)"},
    {"blend", FieldKind::Blend, 0, 0, kAllTypes, &ElementParams::blend, "",
     "`add` (light adds, HDR-correct), `screen` (soft add for display images), `over` (alpha over)"},
}};

}  // namespace

std::span<const FieldSpec> elementFields() { return kFields; }

ElementParams defaultElement(ElementType type) {
    ElementParams p;
    p.type = type;
    switch (type) {
        case ElementType::Glow:  // seed 002: "a gradient from a bright color to a darker color"
            p.size = 0.3f;
            p.color = {1.f, 0.8f, 0.55f};
            p.innerColor = Rgb{1.f, 1.f, 1.f};
            break;
        case ElementType::Ring:  // seed 002: "an antialiased circle of some dark color"
            p.size = 0.12f;
            p.color = {0.35f, 0.45f, 0.8f};
            p.intensity = 0.35f;
            break;
        case ElementType::Streaks:  // seed 002: "Bright white colors usually work best"
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
        case ElementType::Disc:  // seed 002, Figure 11: purple outer ring to a black centre
            p.size = 0.06f;
            p.color = {0.45f, 0.25f, 0.7f};
            p.innerColor = Rgb{0.f, 0.f, 0.f};
            p.softness = 0.15f;
            p.intensity = 0.4f;
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
