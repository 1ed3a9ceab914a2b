// SPDX-License-Identifier: Apache-2.0
#include "elements/ElementKernel.h"

#include <array>
#include <cmath>
#include <numbers>

#include "core/Check.h"
#include "core/Parallel.h"

namespace flarekit {

namespace {
constexpr std::array<std::string_view, kElementTypeCount> kTypeNames = {
    "glow", "ring", "streaks", "rays", "disc", "polygon", "edge-streak", "image"};
Rgb scaled(const Rgb& c, float k) {
    return {c[0] * k, c[1] * k, c[2] * k};
}
}  // namespace

std::optional<ElementType> parseElementType(std::string_view name) {
    for (std::size_t i = 0; i < kTypeNames.size(); ++i) {
        if (kTypeNames[i] == name) return ElementType(i);
    }
    return std::nullopt;
}

std::string_view elementTypeName(ElementType type) {
    return kTypeNames[std::size_t(type)];
}

ElementKernel prepareElement(const ElementParams& params, float radiusPx) {
    FK_CHECK(std::isfinite(radiusPx) && radiusPx > 0.f, "radiusPx=" << radiusPx);
    ElementKernel k;
    k.params = params;
    k.radiusPx = radiusPx;
    k.outer = scaled(params.color, params.intensity);
    k.inner = scaled(params.innerColor.value_or(params.color), params.intensity);
    // A pixel in local units; with a stretch the finer axis sets the antialiasing width.
    k.pixel = 1.f / (radiusPx * std::min(1.f, params.aspect));
    const float rot = params.rotationDeg * std::numbers::pi_v<float> / 180.f;
    k.cosRot = std::cos(rot);
    k.sinRot = std::sin(rot);
    if (params.type == ElementType::Streaks || params.type == ElementType::Rays) {
        k.spikes = makeSpikes(params);
        k.spikeProfile = makeSpikeProfile(params.thickness, k.pixel);
        k.maxHalfWidth = spikeSupport(k.spikeProfile);
    }
    // Support: an ellipse of semi-axes (R*aspect, R) rotated, plus the antialiasing band; an
    // image fills the rotated rectangle of half sides (R*aspect, R).
    const float a = radiusPx * params.aspect, b = radiusPx;
    const float margin = 1.f + 1.f / std::min(1.f, params.aspect);
    if (params.type == ElementType::Image) {
        k.halfExtentX = std::abs(a * k.cosRot) + std::abs(b * k.sinRot) + margin;
        k.halfExtentY = std::abs(a * k.sinRot) + std::abs(b * k.cosRot) + margin;
        return k;
    }
    k.halfExtentX = std::sqrt(a * a * k.cosRot * k.cosRot + b * b * k.sinRot * k.sinRot) + margin;
    k.halfExtentY = std::sqrt(a * a * k.sinRot * k.sinRot + b * b * k.cosRot * k.cosRot) + margin;
    return k;
}

Rgba gradient(const ElementKernel& k, float u, float amount) {
    if (amount <= 0.f) return {};
    const float w = 1.f - u;
    return {amount * (k.outer[0] * u + k.inner[0] * w), amount * (k.outer[1] * u + k.inner[1] * w),
            amount * (k.outer[2] * u + k.inner[2] * w), std::min(amount, 1.f)};
}

Rgba shadeElement(const ElementKernel& k, float dx, float dy) {
    // Into the element's frame: undo the clockwise rotation, then the horizontal stretch.
    const float lx = (dx * k.cosRot + dy * k.sinRot) / (k.params.aspect * k.radiusPx);
    const float ly = (-dx * k.sinRot + dy * k.cosRot) / k.radiusPx;
    if (k.params.type == ElementType::Image) return shadeImage(k, lx, ly);
    if (lx * lx + ly * ly >= (1.f + k.pixel) * (1.f + k.pixel)) return {};
    switch (k.params.type) {
        case ElementType::Glow:
        case ElementType::EdgeStreak:  // the glow's falloff, stretched along the edge
            return shadeGlow(k, lx, ly);
        case ElementType::Ring:
            return shadeRing(k, lx, ly);
        case ElementType::Streaks:
        case ElementType::Rays:
            return shadeSpikes(k, lx, ly);
        case ElementType::Disc:
            return shadeDisc(k, lx, ly);
        case ElementType::Polygon:
            return shadePolygon(k, lx, ly);
        case ElementType::Image:
            break;  // shaded above: its support is a square, not the unit disc
    }
    return {};
}

Image renderElement(const ElementParams& params, float radiusPx) {
    const ElementKernel k = prepareElement(params, radiusPx);
    const int halfW = int(std::ceil(k.halfExtentX)), halfH = int(std::ceil(k.halfExtentY));
    Image image(2 * halfW, 2 * halfH);
    parallelFor(0, image.height(), 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float dy = float(y) + 0.5f - float(halfH);
            for (int x = 0; x < image.width(); ++x)
                image.at(x, y) = shadeElement(k, float(x) + 0.5f - float(halfW), dy);
        }
    });
    return image;
}

}  // namespace flarekit
