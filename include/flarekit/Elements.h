// SPDX-License-Identifier: Apache-2.0
// Procedural flare elements (Tanczos, "The Art of Modeling Lens Flares", 1999: "Parts of a Flare",
// plus the polygonal iris ghost of modern engines). Each element is a pure function of its
// parameters: the same parameters always give the same pixels.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "flarekit/Blend.h"
#include "flarekit/Image.h"
#include "flarekit/Param.h"

namespace flarekit {

enum class ElementType {
    Glow,     //!< main flare glow: the seed's exp falloff, bright centre to darker edge
    Ring,     //!< thin antialiased annulus at the element's rim
    Streaks,  //!< N evenly spaced thin spikes fading with distance
    Rays,     //!< many thin spikes of random angle and length (seeded)
    Disc,     //!< secondary disc: outer-to-inner colour gradient, soft edge
    Polygon,  //!< iris ghost: regular N-blade polygon, soft edge
    //! A glow stretched along the frame edge nearest the light, brightest as the light crosses
    //! that edge and gone `reach` inside or outside it (BCC's Edge Streak, FlareSim's Outside
    //! Source): the flare leaves the frame with the light instead of vanishing at the border.
    EdgeStreak,
    //! A texture drawn as the element: an engine's image-based flare element (Unity's Image
    //! type, Babylon's and three.js's textures) kept as the image itself, scaled so the texture
    //! spans the element's diameter, tinted by `color` x `intensity` (see `texture`).
    Image,
};
inline constexpr int kElementTypeCount = 8;
std::optional<ElementType> parseElementType(std::string_view name);
std::string_view elementTypeName(ElementType type);

//! One element of a flare. Lengths are fractions of the element radius unless stated;
//! kElementParams below gives every field's JSON key, range and documentation.
struct ElementParams {
    ElementType type = ElementType::Glow;
    float t = 1.f;  //!< position on the flare vector: 1 at the light, 0 screen centre, -1 mirrored
    float size = 0.1f;         //!< radius, fraction of the image height
    Rgb color{1.f, 1.f, 1.f};  //!< linear RGB; the edge colour where the element has a gradient
    std::optional<Rgb>
        innerColor;         //!< centre colour of the gradient (glow, disc, polygon); default: color
    float intensity = 1.f;  //!< multiplies the colour (linear)
    float aspect = 1.f;     //!< horizontal stretch: 2 is twice as wide as tall
    float rotationDeg = 0.f;  //!< degrees, clockwise on screen
    float width = 0.06f;      //!< ring width, fraction of radius
    float softness = 0.f;     //!< edge blur width, fraction of radius (0: pixel antialiasing only)
    int count = 4;            //!< streaks: number of spikes; rays: number of rays
    float thickness = 0.01f;  //!< streak/ray width, fraction of radius
    float falloff = 2.f;      //!< streak/ray brightness (1 - r/length)^falloff
    float minLength =
        0.3f;        //!< rays: shortest ray, fraction of radius (lengths uniform in [minLength, 1])
    int blades = 6;  //!< polygon: number of aperture blades
    //! polygon: 0 sharp corners, 1 the inscribed circle: the polygon shrunk by roundness x its
    //! apothem and grown back by a disc of that radius (Unity's SDF roundness).
    float roundness = 0.f;
    std::uint32_t seed = 1;  //!< rays: random seed (same seed, same rays, on every platform)
    BlendMode blend = BlendMode::Add;  //!< how the element composites onto the image
    float reach = 0.25f;  //!< edge streak: fades out this far from the edge, image heights
    //! False: kept in the preset but not drawn (an element switched off while designing, as
    //! Unity's lens-flare elements have a Visible box).
    bool visible = true;
    //! Image elements: the texture file as the preset names it (relative to the preset's
    //! folder) and its pixels, linear RGBA, read when the preset is parsed. Not a table
    //! parameter: a path is not a number (the preset reader handles the "texture" key).
    std::string texture;
    std::shared_ptr<const Image> textureImage;
    //! What another engine's file held for this element and flarekit cannot draw (a curve, a
    //! blend mode it lacks), as compact JSON: kept so converting back restores it. Empty: none.
    std::string source;
};

//! Bit of an element type in Param::appliesTo.
inline constexpr std::uint32_t typeBit(ElementType t) {
    return 1u << unsigned(t);
}
inline constexpr std::uint32_t kAllElementTypes = (1u << kElementTypeCount) - 1;

namespace element_bits {
inline constexpr std::uint32_t kGlow = typeBit(ElementType::Glow),
                               kRing = typeBit(ElementType::Ring),
                               kStreaks = typeBit(ElementType::Streaks),
                               kRays = typeBit(ElementType::Rays),
                               kDisc = typeBit(ElementType::Disc),
                               kPolygon = typeBit(ElementType::Polygon), kSpikes = kStreaks | kRays,
                               kEdgeStreak = typeBit(ElementType::EdgeStreak),
                               kImage = typeBit(ElementType::Image);
}  // namespace element_bits

//! Every element parameter. Ranges are what still gives a sensible image; they exist to catch
//! typos ("size": 40). size [0, 4]: 4 image heights covers the widest anamorphic streak.
//! Colour components [0, 64]: HDR colours above display white, up to a sun-like 64.
inline constexpr Param<ElementParams> kElementParams[] = {
    param<&ElementParams::t>("t", -8, 8, "",
                             "position on the flare vector: 1 at the light, 0 at the screen "
                             "centre, -1 mirrored through it"),
    param<&ElementParams::size>("size", 0, 4, "image heights", "radius"),
    param<&ElementParams::color>("color", 0, 64, "linear RGB",
                                 "colour; the rim colour where the element has a gradient"),
    param<&ElementParams::innerColor>("inner_color", 0, 64, "linear RGB",
                                      "colour at the centre (ring: at its inner edge), blending "
                                      "linearly to `color`; default `color`",
                                      element_bits::kGlow | element_bits::kRing |
                                          element_bits::kDisc | element_bits::kPolygon |
                                          element_bits::kSpikes | element_bits::kEdgeStreak),
    param<&ElementParams::intensity>("intensity", 0, 1000, "", "multiplies the colour"),
    param<&ElementParams::aspect>("aspect", 0.05, 20, "",
                                  "horizontal stretch (2: twice as wide as tall)"),
    param<&ElementParams::rotationDeg>("rotation", -360, 360, "degrees",
                                       "rotation, clockwise on screen"),
    param<&ElementParams::width>("width", 0.001, 1, "radius", "ring width", element_bits::kRing),
    param<&ElementParams::softness>(
        "softness", 0, 1, "radius", "edge blur width (0: one-pixel antialiasing only)",
        element_bits::kRing | element_bits::kDisc | element_bits::kPolygon),
    param<&ElementParams::count>("count", 1, 4096, "", "number of streaks or rays",
                                 element_bits::kSpikes),
    param<&ElementParams::thickness>("thickness", 0.0005, 0.5, "radius",
                                     "width of each streak or ray", element_bits::kSpikes),
    param<&ElementParams::falloff>("falloff", 0, 16, "",
                                   "brightness along a spike: (1 - distance/length)^falloff",
                                   element_bits::kSpikes),
    param<&ElementParams::minLength>("min_length", 0, 1, "radius",
                                     "shortest ray; lengths are uniform in [min_length, 1]",
                                     element_bits::kRays),
    param<&ElementParams::blades>("blades", 3, 32, "", "aperture blades (polygon sides)",
                                  element_bits::kPolygon),
    param<&ElementParams::roundness>("roundness", 0, 1, "",
                                     "corner rounding: 0 sharp, 1 the inscribed circle",
                                     element_bits::kPolygon),
    param<&ElementParams::seed>("seed", 0, 4294967295.0, "",
                                "random seed of the rays (same seed, same rays everywhere)",
                                element_bits::kRays),
    param<&ElementParams::reach>("reach", 0.01, 4, "image heights",
                                 "edge streak: distance from the frame edge (inside or outside) at "
                                 "which it has faded out",
                                 element_bits::kEdgeStreak),
    param<&ElementParams::visible>("visible", 0, 1, "",
                                   "false: kept in the preset but not drawn (switched off)"),
    choice<&ElementParams::blend>("blend", kBlendModeNames,
                                  "`add` (light adds, HDR-correct), `screen` (soft add for display "
                                  "images), `over` (alpha over)"),
};

//! Per-type defaults: ElementParams{} with the fields a type needs set to what looks right.
ElementParams defaultElement(ElementType type);

//! Renders one element centred in an image of 2*ceil(half extent) pixels a side: premultiplied
//! linear RGBA, alpha = coverage. With aspect 1, zero at distances >= radiusPx + 1 pixel from
//! the centre (the rim antialiasing band is at most a pixel wide). radiusPx must be finite, > 0.
Image renderElement(const ElementParams& params, float radiusPx);

}  // namespace flarekit
