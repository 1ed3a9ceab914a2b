// SPDX-License-Identifier: Apache-2.0
// Draws a preset's elements into an image. The image is split into bands of rows run in
// parallel; each band shades only the part of each element's bounding box inside it, so the
// cost is the pixels the elements cover. Elements composite in preset order within a pixel,
// so the result does not depend on the thread count.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/Parallel.h"
#include "elements/ElementKernel.h"
#include "flarekit/Flare.h"

namespace flarekit {

namespace {

//! Elements smaller than this radius (pixels) are below one pixel's footprint and skipped.
constexpr float kMinRadiusPx = 0.5f;
//! Rows per parallel task: enough work per task, small enough to balance two cores.
constexpr int kBandRows = 16;

struct PlacedElement {
    ElementKernel kernel;
    Point centre;
    int x0, y0, x1, y1;  //!< clipped bounding box, half-open
};

std::vector<PlacedElement> placeElements(const Image& image, const Preset& preset, Point light,
                                         float intensity) {
    std::vector<PlacedElement> placed;
    const float height = float(image.height());
    for (const ElementParams& e : preset.elements) {
        const float radius = e.size * height;
        const bool edge = e.type == ElementType::EdgeStreak;
        const EdgePlacement edgeAt =
            edge ? edgeStreakPlacement(light, image.width(), image.height(), e.reach)
                 : EdgePlacement{};
        const float k = e.intensity * preset.intensity * intensity * (edge ? edgeAt.weight : 1.f);
        if (!e.visible || radius < kMinRadiusPx || k <= 0.f || !std::isfinite(k)) continue;
        ElementParams scaled = e;
        scaled.intensity = k;
        if (edge) scaled.rotationDeg += edgeAt.rotationDeg;
        PlacedElement p{
            prepareElement(scaled, radius),
            edge ? edgeAt.centre : flareVectorPoint(light, image.width(), image.height(), e.t),
            0,
            0,
            0,
            0};
        // Clip in double: a light far outside the frame must not overflow int.
        auto clip = [](double v, int hi) { return int(std::clamp(v, 0.0, double(hi))); };
        p.x0 = clip(std::floor(double(p.centre.x) - p.kernel.halfExtentX), image.width());
        p.x1 = clip(std::ceil(double(p.centre.x) + p.kernel.halfExtentX), image.width());
        p.y0 = clip(std::floor(double(p.centre.y) - p.kernel.halfExtentY), image.height());
        p.y1 = clip(std::ceil(double(p.centre.y) + p.kernel.halfExtentY), image.height());
        if (p.x0 < p.x1 && p.y0 < p.y1) placed.push_back(std::move(p));
    }
    return placed;
}

}  // namespace

EdgePlacement edgeStreakPlacement(Point light, int width, int height, float reach) {
    const float w = float(width), h = float(height);
    EdgePlacement p;
    const float toLeft = light.x, toRight = w - light.x, toTop = light.y, toBottom = h - light.y;
    const bool inside = std::min({toLeft, toRight, toTop, toBottom}) >= 0.f;
    float distance = 0.f;
    if (inside) {  // the nearest edge, and the point of it opposite the light
        const float nearest = std::min({toLeft, toRight, toTop, toBottom});
        distance = nearest;
        const bool side = nearest == toLeft || nearest == toRight;
        p.rotationDeg = side ? 90.f : 0.f;
        p.centre = side ? Point{nearest == toLeft ? 0.f : w, light.y}
                        : Point{light.x, nearest == toTop ? 0.f : h};
    } else {  // the light clamped into the frame, along the edge it is beyond the most
        p.centre = {std::clamp(light.x, 0.f, w), std::clamp(light.y, 0.f, h)};
        const float dx = light.x - p.centre.x, dy = light.y - p.centre.y;
        distance = std::sqrt(dx * dx + dy * dy);
        p.rotationDeg = std::abs(dx) > std::abs(dy) ? 90.f : 0.f;
    }
    const float band = reach * h;
    const float u = band > 0.f ? std::clamp(distance / band, 0.f, 1.f) : 1.f;
    p.weight = 1.f - u * u * (3.f - 2.f * u);
    return p;
}

namespace {
//! One element's spike evaluations, and 0 for other element types.
double spikeWork(const ElementParams& e, int width, int height) {
    if (!e.visible || (e.type != ElementType::Streaks && e.type != ElementType::Rays)) return 0;
    const double radius = double(e.size) * height;
    if (radius < kMinRadiusPx) return 0;
    const SpikeProfile profile = makeSpikeProfile(e.thickness, float(1.0 / radius));
    const double support = double(spikeSupport(profile)) * radius;  // pixels
    const double reach = std::min(radius, std::hypot(double(width), double(height)));
    return double(e.count) * (2.0 * support * reach + support * support);
}
}  // namespace

double flareSpikeWork(const Preset& preset, int width, int height) {
    double work = 0;
    for (const ElementParams& e : preset.elements) work += spikeWork(e, width, height);
    return work;
}

Status checkFlareWork(const Preset& preset, int width, int height, int flares,
                      const std::string& what) {
    const double work = flareSpikeWork(preset, width, height) * std::max(1, flares);
    if (work <= kMaxSpikeWork) return Ok{};
    std::size_t worst = 0;
    for (std::size_t i = 1; i < preset.elements.size(); ++i) {
        if (spikeWork(preset.elements[i], width, height) >
            spikeWork(preset.elements[worst], width, height))
            worst = i;
    }
    const ElementParams& e = preset.elements[worst];
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s: elements[%zu] (%s, count %d, size %g, thickness %g) at %dx%d needs an "
                  "estimated %.3g spike evaluations%s, over the limit of %.3g (minutes of work): "
                  "lower its count, size or thickness",
                  what.c_str(), worst, std::string(elementTypeName(e.type)).c_str(), e.count,
                  double(e.size), double(e.thickness), width, height, work,
                  flares > 1 ? (" for " + std::to_string(flares) + " flares").c_str() : "",
                  kMaxSpikeWork);
    return invalidInput(text);
}

FlareStats renderFlare(Image& image, const Preset& preset, Point light, float intensity) {
    FlareStats stats;
    if (image.empty() || !std::isfinite(light.x) || !std::isfinite(light.y)) return stats;
    const std::vector<PlacedElement> placed = placeElements(image, preset, light, intensity);
    const int bands = (image.height() + kBandRows - 1) / kBandRows;
    parallelFor(0, bands, 1, [&](int b0, int b1) {
        std::vector<Rgba> span(std::size_t(image.width()));
        const int yBegin = b0 * kBandRows, yEnd = std::min(image.height(), b1 * kBandRows);
        for (const PlacedElement& p : placed) {
            const int y0 = std::max(yBegin, p.y0), y1 = std::min(yEnd, p.y1);
            for (int y = y0; y < y1; ++y) {
                const float dy = float(y) + 0.5f - p.centre.y;
                for (int x = p.x0; x < p.x1; ++x) {
                    span[std::size_t(x - p.x0)] =
                        shadeElement(p.kernel, float(x) + 0.5f - p.centre.x, dy);
                }
                compositeSpan(p.kernel.params.blend, reinterpret_cast<const float*>(span.data()),
                              image.row(y) + std::size_t(p.x0) * 4, std::size_t(p.x1 - p.x0));
            }
        }
    });
    stats.elementsDrawn = placed.size();
    for (const PlacedElement& p : placed)
        stats.pixelsShaded += std::size_t(p.x1 - p.x0) * std::size_t(p.y1 - p.y0);
    return stats;
}

FlareStats flareLights(Image& image, const Preset& preset, const LightSearch& search,
                       float intensity) {
    FlareStats total;
    for (const LightCandidate& light : search.lights) {
        const FlareStats s =
            renderFlare(image, preset, light.position, intensity * light.flareScale);
        total.elementsDrawn += s.elementsDrawn;
        total.pixelsShaded += s.pixelsShaded;
    }
    return total;
}

}  // namespace flarekit
