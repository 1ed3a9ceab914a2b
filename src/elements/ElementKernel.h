// SPDX-License-Identifier: Apache-2.0
// An element prepared for shading: its parameters resolved to pixels, plus derived tables.
// shadeElement() is the per-pixel function every renderer calls (contact sheet, flare, tests).
#pragma once

#include <vector>

#include "flarekit/Elements.h"

namespace flarekit {

struct Spike {
    float angle;   //!< radians in [0, 2*pi), measured in the element's local frame
    float length;  //!< fraction of radius
    float weight;  //!< brightness multiplier
    float cosAngle = 1.f, sinAngle = 0.f;  //!< of `angle`, so a pixel costs no trigonometry
};

//! Brightness across a spike at perpendicular distance u (local units): a Gaussian core plus a
//! soft exponential wing, both widened to at least a pixel-sized footprint (with their peak
//! lowered to keep their energy) so a thin spike is antialiased instead of aliased.
struct SpikeProfile {
    float coreSigma = 1.f, coreAmp = 1.f;  //!< Gaussian core: exp(-u^2 / (2 sigma^2)) * amp
    float wingScale = 1.f, wingAmp = 0.f;  //!< wing: exp(-|u| / scale) * amp
};
float spikeAcross(const SpikeProfile& profile, float u);
SpikeProfile makeSpikeProfile(float thickness, float pixel);
//! Distance past which the profile is taken as zero.
float spikeSupport(const SpikeProfile& profile);

struct ElementKernel {
    ElementParams params;
    Rgb outer{}, inner{};  //!< colour x intensity at the rim and at the centre
    float radiusPx = 1.f;  //!< R
    float pixel = 1.f;     //!< one pixel in local units (fractions of R), for antialiasing
    float cosRot = 1.f, sinRot = 0.f;
    std::vector<Spike> spikes;                   //!< streaks/rays, sorted by angle
    SpikeProfile spikeProfile;                   //!< streaks/rays: brightness across a spike
    float maxHalfWidth = 0.f;                    //!< where the spike profile ends (local units)
    float halfExtentX = 0.f, halfExtentY = 0.f;  //!< support half-size in pixels (bounding box)
};

ElementKernel prepareElement(const ElementParams& params, float radiusPx);

//! Premultiplied RGBA at pixel offset (dx, dy) from the element centre (pixel centre minus
//! element centre, in pixels; +y down).
Rgba shadeElement(const ElementKernel& kernel, float dx, float dy);

// Per-type shaders over local coordinates (x, y) in fractions of the radius, d = |(x, y)|.
Rgba shadeGlow(const ElementKernel& k, float x, float y);
Rgba shadeRing(const ElementKernel& k, float x, float y);
Rgba shadeSpikes(const ElementKernel& k, float x, float y);
Rgba shadeDisc(const ElementKernel& k, float x, float y);
Rgba shadePolygon(const ElementKernel& k, float x, float y);
//! The texture over the square [-1, 1]^2 (bilinear, clear outside), premultiplied by its alpha
//! and tinted by k.outer.
Rgba shadeImage(const ElementKernel& k, float x, float y);
std::vector<Spike> makeSpikes(const ElementParams& params);
//! The glow falloff g(d) of Glow.cpp: 1 at the centre, 0 at and past the rim.
float glowProfile(float d);

//! Colour between k.inner (u = 0) and k.outer (u = 1), scaled by `amount`, alpha = amount.
Rgba gradient(const ElementKernel& k, float u, float amount);

}  // namespace flarekit
