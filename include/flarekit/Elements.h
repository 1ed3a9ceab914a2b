// Procedural flare elements (Tanczos 1999, seed 002 "Parts of a Flare", plus the polygonal
// iris ghost of modern engines). Each element is a pure function of its parameters: the same
// parameters always give the same pixels.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "flarekit/Blend.h"
#include "flarekit/Image.h"

namespace flarekit {

using Rgb = std::array<float, 3>;  //!< linear-light RGB

enum class ElementType {
    Glow,     //!< main flare glow: the seed's exp falloff, bright centre to darker edge
    Ring,     //!< thin antialiased annulus at the element's rim
    Streaks,  //!< N evenly spaced thin spikes fading with distance
    Rays,     //!< many thin spikes of random angle and length (seeded)
    Disc,     //!< secondary disc: outer-to-inner colour gradient, soft edge
    Polygon,  //!< iris ghost: regular N-blade polygon, soft edge
};
inline constexpr int kElementTypeCount = 6;
std::optional<ElementType> parseElementType(std::string_view name);
std::string_view elementTypeName(ElementType type);

//! One element of a flare. Lengths are fractions of the element radius unless stated; the
//! table in src/flare/ParamTable.cpp gives every field's JSON key, range and documentation.
struct ElementParams {
    ElementType type = ElementType::Glow;
    float t = 1.f;              //!< position on the flare vector: 1 at the light, 0 screen centre, -1 mirrored
    float size = 0.1f;          //!< radius, fraction of the image height
    Rgb color{1.f, 1.f, 1.f};   //!< linear RGB; the edge colour where the element has a gradient
    std::optional<Rgb> innerColor;  //!< centre colour of the gradient (glow, disc, polygon); default: color
    float intensity = 1.f;      //!< multiplies the colour (linear)
    float aspect = 1.f;         //!< horizontal stretch: 2 is twice as wide as tall
    float rotationDeg = 0.f;    //!< degrees, clockwise on screen
    float width = 0.06f;        //!< ring width, fraction of radius
    float softness = 0.f;       //!< edge blur width, fraction of radius (0: pixel antialiasing only)
    int count = 4;              //!< streaks: number of spikes; rays: number of rays
    float thickness = 0.01f;    //!< streak/ray width, fraction of radius
    float falloff = 2.f;        //!< streak/ray brightness (1 - r/length)^falloff
    float minLength = 0.3f;     //!< rays: shortest ray, fraction of radius (lengths uniform in [minLength, 1])
    int blades = 6;             //!< polygon: number of aperture blades
    std::uint32_t seed = 1;     //!< rays: random seed (same seed, same rays, on every platform)
    BlendMode blend = BlendMode::Add;  //!< how the element composites onto the image
};

//! Renders one element centred in an image of 2*ceil(half extent) pixels a side: premultiplied
//! linear RGBA, alpha = coverage. With aspect 1, zero at distances >= radiusPx + 1 pixel from
//! the centre (the rim antialiasing band is at most a pixel wide). radiusPx must be finite, > 0.
Image renderElement(const ElementParams& params, float radiusPx);

}  // namespace flarekit
