// SPDX-License-Identifier: Apache-2.0
// `lens render`: each source's ghosts as traced meshes (Hullin et al., "Physically-Based
// Real-Time Lens Flare Rendering", SIGGRAPH 2011): a grid of rays over the first surface is
// traced along the ghost's path without clipping; every grid triangle is rasterised on the
// sensor with the irradiance its area change implies, and masked per pixel by the iris polygon
// (from the interpolated stop coordinates) and by the clear apertures (the interpolated largest
// r / semi-aperture), so ghosts are the aperture seen through the path: cut by vignetting,
// stretched off axis, as large as their defocus. Then the aperture's diffraction starburst and
// a veiling-glare halo.
#include <algorithm>
#include <cmath>

#include "core/Interrupt.h"
#include "core/Parallel.h"
#include "core/Smoothstep.h"
#include "flarekit/Color.h"
#include "flarekit/Lens.h"
#include "flarekit/ParamText.h"
#include "lens/GhostMesh.h"
#include "lens/GhostPlacement.h"
#include "lens/LensTrace.h"
#include "lens/Spectrum.h"
#include "lens/Starburst.h"

namespace flarekit {

namespace lens {

TrianglePlan planTriangle(const Mesh& m, const Iris& iris, const RayResult& a, const RayResult& b,
                          const RayResult& c) {
    TrianglePlan plan;
    // A vertex off the sub-pixel grid (a fold of the mesh toward infinity): the triangle is a
    // sliver whose energy is spread over far more than any frame, and no rasteriser can place
    // its edges exactly; it is not drawn.
    for (const RayResult* r : {&a, &b, &c}) {
        if (!(std::fabs(r->x) < kSubpixelReach && std::fabs(r->y) < kSubpixelReach)) return plan;
    }
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area == 0.0) return plan;
    const double pixels = std::fabs(area) * 0.5;
    plan.density = 1.0 / std::max(pixels, 1.0);
    const double peak = plan.density * std::max({a.throughput, b.throughput, c.throughput}) *
                        std::max({m.weight[0], m.weight[1], m.weight[2]});
    if (peak < kInvisible) return plan;
    if (std::min({a.vignette, b.vignette, c.vignette}) > 1.0 + kMaskEdge) return plan;
    for (int k = 0; k < a.stopCrossings; ++k) {
        if (irisCover(iris, a, b, c, k) == Cover::Outside) return plan;
    }
    plan.draw = true;
    plan.point = pixels < 1.0;
    return plan;
}

std::vector<std::array<RayResult, 3>> clipToImage(const RayResult& a, const RayResult& b,
                                                  const RayResult& c, int width, int height) {
    const double w = width, h = height;
    if (insideImage(a, b, c, width, height)) return {{a, b, c}};
    // The point of the segment p-q where `f` (linear) is zero, attributes included.
    const auto cut = [](const RayResult& p, const RayResult& q, double fp, double fq) {
        const double t = fp / (fp - fq);
        RayResult r = p;
        r.x = snapToSubpixel(p.x + (q.x - p.x) * t), r.y = snapToSubpixel(p.y + (q.y - p.y) * t);
        r.throughput = p.throughput + (q.throughput - p.throughput) * t;
        r.vignette = p.vignette + (q.vignette - p.vignette) * t;
        for (std::size_t i = 0; i < r.stop.size(); ++i)
            r.stop[i] = p.stop[i] + (q.stop[i] - p.stop[i]) * t;
        return r;
    };
    std::vector<RayResult> polygon{a, b, c}, next;
    const std::array<std::array<double, 3>, 4> planes{
        {{1, 0, 0}, {-1, 0, w}, {0, 1, 0}, {0, -1, h}}};
    for (const auto& pl : planes) {
        next.clear();
        const auto f = [&](const RayResult& r) { return pl[0] * r.x + pl[1] * r.y + pl[2]; };
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const RayResult &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
            const double fp = f(p), fq = f(q);
            if (fp >= 0) next.push_back(p);
            if ((fp >= 0) != (fq >= 0)) next.push_back(cut(p, q, fp, fq));
        }
        polygon.swap(next);
        if (polygon.size() < 3) return {};
    }
    std::vector<std::array<RayResult, 3>> fan;
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        fan.push_back({polygon[0], polygon[i], polygon[i + 1]});
    return fan;
}

}  // namespace lens

namespace {

using lens::Cover;
using lens::edgeMask;
using lens::fieldAngle;
using lens::kMaskEdge;
using lens::Mesh;
using lens::PickedGhosts;
using lens::pickGhosts;
using lens::pixelIndex;
using lens::RayResult;
using lens::SensorMap;
using lens::TraceLens;

//! Traces the mesh into `m`, reusing its rays' storage: a light after the first fills the
//! meshes the one before it left (no allocation, no page faults on fresh memory per source).
void traceMesh(const TraceLens& t, const std::vector<lens::PathStep>& path, lens::Vec dir, int side,
               const SensorMap& map, Mesh& m) {
    const double sa = t.surfaces.front().semiAperture;
    // The grid's spacing stays that of `side` vertices over the clear diameter; an oblique beam
    // adds rows and columns so that the light entering past the square is drawn too (the first
    // surface's clear aperture masks the rest per pixel).
    const double spacing = 2.0 * sa / (side - 1);
    const int margin = lens::beamMargin(t, dir, spacing);
    m.side = side + 2 * margin;
    m.rays.resize(std::size_t(m.side) * std::size_t(m.side));
    m.minY = 1e30, m.maxY = -1e30;
    for (int iy = 0; iy < m.side; ++iy) {
        for (int ix = 0; ix < m.side; ++ix) {
            const double x = -sa + (ix - margin) * spacing, y = -sa + (iy - margin) * spacing;
            RayResult r = lens::traceRay(t, path, lens::beamOrigin(t, dir, x, y), dir, false);
            if (r.alive) {
                r.x = lens::snapToSubpixel(map.toPxX(r.x)),
                r.y = lens::snapToSubpixel(map.toPxY(r.y));
                m.minY = std::min(m.minY, r.y), m.maxY = std::max(m.maxY, r.y);
            }
            m.rays[std::size_t(iy) * std::size_t(m.side) + std::size_t(ix)] = r;
        }
    }
}

void rasterisePiece(const Mesh& m, const lens::Iris& iris, const RayResult& a, const RayResult& b,
                    const RayResult& c, double density, bool vignetteEdge,
                    const std::array<bool, lens::kMaxStopCrossings>& irisEdge, int crossings,
                    Image& out, int rowBegin, int rowEnd);

//! Adds the triangle (a, b, c) of `m` to rows [rowBegin, rowEnd) of `out` (RGB in RGBA).
void rasterise(const Mesh& m, const lens::Iris& iris, const RayResult& a, const RayResult& b,
               const RayResult& c, Image& out, int rowBegin, int rowEnd) {
    const lens::TrianglePlan plan = lens::planTriangle(m, iris, a, b, c);
    if (!plan.draw) return;
    const double density = plan.density;
    // Which masks can cut this triangle: the others are 1 over all of it (each mask is convex
    // and its coordinates vary linearly, so vertices inside by the edge's width mean all is).
    const bool vignetteEdge = std::max({a.vignette, b.vignette, c.vignette}) >= 1.0 - kMaskEdge;
    std::array<bool, lens::kMaxStopCrossings> irisEdge{};
    const int crossings = a.stopCrossings;
    for (int k = 0; k < crossings; ++k)
        irisEdge[std::size_t(k)] = lens::irisCover(iris, a, b, c, k) != Cover::Inside;
    if (plan.point) {
        // Smaller than a pixel (a focused ghost, a caustic): it may cover no pixel centre, so
        // its whole energy goes to the pixel under its centroid, masked there.
        const double cx = (a.x + b.x + c.x) / 3, cy = (a.y + b.y + c.y) / 3;
        if (!(cx >= 0 && cx < out.width() && cy >= rowBegin && cy < rowEnd)) return;
        const int px = int(cx), py = int(cy);
        double mask = edgeMask((a.vignette + b.vignette + c.vignette) / 3);
        for (int k = 0; k < crossings; ++k) {
            const std::size_t i = std::size_t(2 * k);
            mask *= edgeMask(lens::irisRadius(iris, (a.stop[i] + b.stop[i] + c.stop[i]) / 3,
                                              (a.stop[i + 1] + b.stop[i + 1] + c.stop[i + 1]) / 3));
        }
        const double v = mask * (a.throughput + b.throughput + c.throughput) / 3;
        float* p = out.row(py) + 4 * px;
        p[0] += float(v * m.weight[0]), p[1] += float(v * m.weight[1]),
            p[2] += float(v * m.weight[2]);
        return;
    }
    // Most triangles lie inside the image and are drawn as they are (no copy, no allocation).
    if (lens::insideImage(a, b, c, out.width(), out.height())) {
        rasterisePiece(m, iris, a, b, c, density, vignetteEdge, irisEdge, crossings, out, rowBegin,
                       rowEnd);
        return;
    }
    for (const auto& piece : lens::clipToImage(a, b, c, out.width(), out.height()))
        rasterisePiece(m, iris, piece[0], piece[1], piece[2], density, vignetteEdge, irisEdge,
                       crossings, out, rowBegin, rowEnd);
}

void rasterisePiece(const Mesh& m, const lens::Iris& iris, const RayResult& a, const RayResult& b,
                    const RayResult& c, double density, bool vignetteEdge,
                    const std::array<bool, lens::kMaxStopCrossings>& irisEdge, int crossings,
                    Image& out, int rowBegin, int rowEnd) {
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area == 0.0) return;
    const int x0 = pixelIndex(std::min({a.x, b.x, c.x}), 0, out.width());
    const int x1 = pixelIndex(std::ceil(std::max({a.x, b.x, c.x})), -1, out.width() - 1);
    const int y0 = pixelIndex(std::min({a.y, b.y, c.y}), rowBegin, rowEnd);
    const int y1 = pixelIndex(std::ceil(std::max({a.y, b.y, c.y})), rowBegin - 1, rowEnd - 1);
    const double inv = 1.0 / area;
    // A pixel centre exactly on an edge belongs to one of the two triangles sharing it, by the
    // rule GPUs apply in framebuffer memory order, whose first row is the window's bottom (Mesa's
    // llvmpipe: D3D's top-left rule there): left edges and, of horizontal edges, the bottom ones
    // of this y-down image. The CPU then covers the pixels a GPU does; vertices sit on the 1/256
    // grid, so these tests are exact. (Taking the top edges instead put whole rows of a ghost's
    // boundary triangles in one rasteriser and not the other: LensParity's worst values.)
    const double sign = area > 0 ? 1.0 : -1.0;
    const auto covers = [&](double e, const RayResult& from, const RayResult& to) {
        if (e != 0) return e * sign > 0;
        const double dx = (to.x - from.x) * sign, dy = (to.y - from.y) * sign;
        return dy < 0 || (dy == 0 && dx < 0);
    };
    for (int y = y0; y <= y1; ++y) {
        float* row = out.row(y);
        const double py = y + 0.5;
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5;
            // Edge functions of the pixel centre: twice the signed areas opposite each vertex.
            const double ea = (c.x - b.x) * (py - b.y) - (c.y - b.y) * (px - b.x);
            const double eb = (a.x - c.x) * (py - c.y) - (a.y - c.y) * (px - c.x);
            const double ec = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
            if (!covers(ea, b, c) || !covers(eb, c, a) || !covers(ec, a, b)) continue;
            // Barycentric weights.
            const double wa = ea * inv, wb = eb * inv, wc = ec * inv;
            double mask = 1.0;
            if (vignetteEdge) mask = edgeMask(wa * a.vignette + wb * b.vignette + wc * c.vignette);
            for (int k = 0; k < crossings && mask > 0; ++k) {
                if (!irisEdge[std::size_t(k)]) continue;
                const std::size_t i = std::size_t(2 * k);
                const double sx = wa * a.stop[i] + wb * b.stop[i] + wc * c.stop[i];
                const double sy = wa * a.stop[i + 1] + wb * b.stop[i + 1] + wc * c.stop[i + 1];
                mask *= edgeMask(lens::irisRadius(iris, sx, sy));
            }
            if (mask <= 0) continue;
            const double v =
                mask * density * (wa * a.throughput + wb * b.throughput + wc * c.throughput);
            float* p = row + 4 * x;
            p[0] += float(v * m.weight[0]), p[1] += float(v * m.weight[1]),
                p[2] += float(v * m.weight[2]);
        }
    }
}

//! Rows [rowBegin, rowEnd) of every triangle of every mesh.
void rasteriseBand(const std::vector<Mesh>& meshes, const lens::Iris& iris, Image& out,
                   int rowBegin, int rowEnd) {
    for (const Mesh& m : meshes) {
        if (m.maxY < rowBegin || m.minY > rowEnd) continue;
        lens::forEachTriangle(m, [&](const RayResult& a, const RayResult& b, const RayResult& c) {
            if (std::max({a.y, b.y, c.y}) < rowBegin || std::min({a.y, b.y, c.y}) > rowEnd) return;
            rasterise(m, iris, a, b, c, out, rowBegin, rowEnd);
        });
    }
}

//! Which ghosts to draw: the brightest `count` at the angle of the brightest source.

//! The starburst of one source: the PSF scaled by wavelength (Fraunhofer: the pattern's size
//! goes as lambda), summed over the samples, `share` of its energy.
void addStarburst(const Lens& lens, const lens::PupilDirt& dirt,
                  const std::vector<lens::SpectralSample>& samples, const LensLight& light,
                  double share, double radiusPx, Image& out) {
    if (share <= 0 || radiusPx < 1) return;
    constexpr int kPsfSize = 512;
    const lens::Psf& psf = lens::aperturePsf(lens.aperture, dirt, kPsfSize);
    // radiusPx is where the PSF grid's edge lands at 550 nm; the kernel reaches it at 700 nm.
    const double reach = radiusPx * 700.0 / 550.0;
    const int x0 = pixelIndex(light.x - reach, 0, out.width()),
              x1 = pixelIndex(light.x + reach, -1, out.width() - 1);
    const int y0 = pixelIndex(light.y - reach, 0, out.height()),
              y1 = pixelIndex(light.y + reach, -1, out.height() - 1);
    if (x0 > x1 || y0 > y1) return;
    // Sampled at pixel centres the PSF's sum over the pattern's whole footprint (inside the
    // frame or not) is not exactly its integral: each wavelength's pattern is normalised by
    // that sum, so the pixels hold exactly `share` of the light, less what falls off the frame.
    const int fx0 = int(std::floor(-reach)), fx1 = int(std::ceil(reach));
    // The PSF is one period of a discrete transform on a square grid: a spike is cut where it
    // meets the square, at a distance that depends on its direction, and its tail wraps round
    // to the opposite edge, where it shows as a hooked tip. A radial window ends every spike
    // alike, well inside the grid: 1 out to kSpikeFadeStart of the grid's half size, easing
    // (smoothstep) to 0 at kSpikeFadeEnd.
    constexpr double kSpikeFadeStart = 0.55, kSpikeFadeEnd = 0.9;
    const auto windowed = [&](double x, double y) {
        const double r = std::sqrt(x * x + y * y) / (kPsfSize / 2.0);
        if (r >= kSpikeFadeEnd) return 0.0;
        return smoothstep01((kSpikeFadeEnd - r) / (kSpikeFadeEnd - kSpikeFadeStart)) *
               lens::samplePsf(psf, x, y);
    };
    for (const lens::SpectralSample& s : samples) {
        const double samplesPerPixel = (kPsfSize / 2.0) / (radiusPx * s.lambdaNm / 550.0);
        const double ox = light.x - std::floor(light.x), oy = light.y - std::floor(light.y);
        double total = 0;
        for (int dy = fx0; dy <= fx1; ++dy)
            for (int dx = fx0; dx <= fx1; ++dx)
                total +=
                    windowed((dx + 0.5 - ox) * samplesPerPixel, (dy + 0.5 - oy) * samplesPerPixel);
        if (total <= 0) continue;
        std::array<double, 3> k{};
        for (int c = 0; c < 3; ++c)
            k[std::size_t(c)] =
                share * light.energy[std::size_t(c)] * s.weight[std::size_t(c)] / total;
        parallelFor(y0, y1 + 1, 16, [&](int begin, int end) {
            for (int y = begin; y < end; ++y) {
                float* row = out.row(y);
                for (int x = x0; x <= x1; ++x) {
                    const double v = windowed((x + 0.5 - light.x) * samplesPerPixel,
                                              (y + 0.5 - light.y) * samplesPerPixel);
                    if (v == 0.0) continue;
                    float* p = row + 4 * x;
                    p[0] += float(v * k[0]), p[1] += float(v * k[1]), p[2] += float(v * k[2]);
                }
            }
        });
    }
}

//! Veiling glare: scattering in the glass and the barrel spreads `share` of the light as a
//! broad halo, here the kernel (1 + (r/r0)^2)^-1.5 whose integral over the plane is 2 pi r0^2.
//! It is cut at 40 r0, where 97.5% of it has been drawn.
void addGlare(const LensLight& light, double share, double r0, Image& out) {
    if (share <= 0 || r0 <= 0) return;
    const double reach = 40 * r0;
    const int x0 = pixelIndex(light.x - reach, 0, out.width()),
              x1 = pixelIndex(light.x + reach, -1, out.width() - 1);
    const int y0 = pixelIndex(light.y - reach, 0, out.height()),
              y1 = pixelIndex(light.y + reach, -1, out.height() - 1);
    if (x0 > x1 || y0 > y1) return;
    const double norm = share / (2 * M_PI * r0 * r0);
    parallelFor(y0, y1 + 1, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            float* row = out.row(y);
            const double dy = (y + 0.5 - light.y) / r0;
            for (int x = x0; x <= x1; ++x) {
                const double dx = (x + 0.5 - light.x) / r0;
                const double q = 1.0 + dx * dx + dy * dy;
                const double v = norm / (q * std::sqrt(q));
                float* p = row + 4 * x;
                p[0] += float(v * light.energy[0]), p[1] += float(v * light.energy[1]),
                    p[2] += float(v * light.energy[2]);
            }
        }
    });
}

//! The CPU rasteriser: each light's triangles in row bands over the cores.
class CpuGhostDrawer final : public lens::GhostDrawer {
  public:
    CpuGhostDrawer(int width, int height) : m_image(width, height) {}
    Status draw(const std::vector<Mesh>& meshes, const lens::Iris& iris) override {
        constexpr int kBand = 32;
        const int height = m_image.height();
        parallelFor(0, (height + kBand - 1) / kBand, 1, [&](int begin, int end) {
            for (int band = begin; band < end && !interrupted(); ++band)
                rasteriseBand(meshes, iris, m_image, band * kBand,
                              std::min(height, (band + 1) * kBand));
        });
        if (interrupted()) return interruptedError("lens render: stopped while drawing ghosts");
        return Ok{};
    }
    Status finish(Image& ghosts) override {
        ghosts = std::move(m_image);
        return Ok{};
    }

  private:
    Image m_image;
};

void setOpaque(Image& image) {
    for (int y = 0; y < image.height(); ++y) {
        float* row = image.row(y);
        for (int x = 0; x < image.width(); ++x) row[4 * x + 3] = 1.f;
    }
}

}  // namespace

Image lensFlareSum(const LensFlareLayers& layers) {
    Image flare(layers.ghosts.width(), layers.ghosts.height());
    for (std::size_t i = 0; i < flare.pixelCount() * 4; ++i)
        flare.data()[i] = i % 4 == 3 ? 1.f
                                     : layers.ghosts.data()[i] + layers.starburst.data()[i] +
                                           layers.glare.data()[i];
    return flare;
}

Result<LensFlareLayers> renderLensFlare(const Lens& lens, int width, int height,
                                        const std::vector<LensLight>& lights,
                                        const LensRenderOptions& options) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        return invalidInput("lens render: expected an image of 1 to " +
                            std::to_string(kMaxImageSide) + " pixels a side");
    CpuGhostDrawer drawer(width, height);
    return lens::renderLensFlareWith(lens, width, height, lights, options, drawer);
}

Result<LensFlareLayers> lens::renderLensFlareWith(const Lens& lens, int width, int height,
                                                  const std::vector<LensLight>& lights,
                                                  const LensRenderOptions& options,
                                                  GhostDrawer& drawer) {
    if (Status s = validateParams(
            options, std::span<const Param<LensRenderOptions>>(kLensRenderParams), "lens render");
        !s)
        return s.error();
    if (options.spectral > 0 && options.spectral < 3)
        return invalidInput("--spectral: expected 0 (RGB) or at least 3 samples, got " +
                            std::to_string(options.spectral));
    LensFlareLayers layers{Image(), Image(width, height), Image(width, height)};
    SensorMap map;
    map.width = width, map.height = height;
    map.mmPerPixel = std::min(lens.sensor.width / width, lens.sensor.height / height);
    const auto samples = lens::spectralSamples(options.spectral);
    const auto starburstSamples = lens::spectralSamples(options.starburstSamples);
    std::vector<TraceLens> traces;
    for (const auto& s : samples) traces.push_back(lens::prepareTrace(lens, s.lambdaNm));
    const TraceLens dLine = lens::prepareTrace(lens, kLineD);
    const double focal = paraxial(lens).focalLength;
    const double diagonal = std::hypot(double(width), double(height));
    lens::PupilDirt dirt{options.dirt, options.dirtSeed, options.pupilMask.get(), 0};
    if (dirt.mask) dirt.maskHash = lens::pupilMaskHash(*dirt.mask);
    const double sa = lens.surfaces.front().semiAperture;

    std::size_t brightest = 0;
    for (std::size_t i = 1; i < lights.size(); ++i) {
        const auto sum = [](const LensLight& l) { return l.energy[0] + l.energy[1] + l.energy[2]; };
        if (sum(lights[i]) > sum(lights[brightest])) brightest = i;
    }
    PickedGhosts picked;
    if (!lights.empty()) {
        const LensLight& l = lights[brightest];
        picked = pickGhosts(lens, fieldAngle(dLine, focal, map.toMmX(l.x), map.toMmY(l.y)),
                            options.ghosts);
    }
    const std::vector<std::array<int, 2>>& ghosts = picked.pairs;
    // Flux level: one factor for every ghost of every light, so their traced ratios stay.
    const double ghostGain = options.ghostLevel == GhostLevel::Flux && picked.share > 0
                                 ? options.ghostGain * kFluxGhostShare / picked.share
                                 : options.ghostGain;
    const int side = options.gridSide;
    // Each grid cell is (2 sa / (side - 1))^2 of the entrance; a triangle half of it, and the
    // light entering is spread over the first surface's clear disc.
    const double cell = 2.0 * sa / (side - 1);
    const double triangleShare = 0.5 * cell * cell / (M_PI * sa * sa);
    const int total = int(lights.size());
    std::vector<Mesh> meshes;
    for (int done = 0; done < total; ++done) {
        const LensLight& light = lights[std::size_t(done)];
        const auto stopped = [total](int drawn) {
            return interruptedError("lens render: " + std::to_string(drawn) + " of " +
                                    std::to_string(total) + " sources drawn, nothing written");
        };
        if (interrupted()) return stopped(done);
        const auto angle = fieldAngle(dLine, focal, map.toMmX(light.x), map.toMmY(light.y));
        const lens::Vec dir = lens::beamDirection(angle[0], angle[1]);
        meshes.resize(ghosts.size() * samples.size());
        parallelFor(0, int(meshes.size()), 1, [&](int begin, int end) {
            for (int k = begin; k < end && !interrupted(); ++k) {
                const std::size_t g = std::size_t(k) / samples.size(),
                                  w = std::size_t(k) % samples.size();
                const auto path =
                    lens::ghostPath(int(lens.surfaces.size()), ghosts[g][0], ghosts[g][1]);
                Mesh& m = meshes[std::size_t(k)];
                traceMesh(traces[w], path, dir, side, map, m);
                // The lens's look for this pair of surfaces (ghost_pairs) on top of the trace.
                const auto look = lens.ghostPairFactor(ghosts[g][0], ghosts[g][1]);
                for (int c = 0; c < 3; ++c)
                    m.weight[std::size_t(c)] = ghostGain * light.energy[std::size_t(c)] *
                                               samples[w].weight[std::size_t(c)] * triangleShare *
                                               look[std::size_t(c)];
            }
        });
        if (interrupted()) return stopped(done);
        if (Status s = drawer.draw(meshes, dLine.iris); !s) {
            if (s.error().code == ErrorCode::Interrupted) return stopped(done);
            return s.error();
        }
        addStarburst(lens, dirt, starburstSamples, light, options.starburst,
                     options.starburstSize * diagonal, layers.starburst);
        addGlare(light, options.glare, 0.01 * diagonal, layers.glare);
        if (options.progress && !options.progress(done + 1, total)) return stopped(done + 1);
    }
    if (Status s = drawer.finish(layers.ghosts); !s) return s.error();
    setOpaque(layers.ghosts), setOpaque(layers.starburst), setOpaque(layers.glare);
    return layers;
}

std::vector<LensLight> brightSources(const Image& image, double threshold, int cell,
                                     int maxSources) {
    std::vector<LensLight> cells;
    if (cell < 1) cell = 1;
    const int cw = (image.width() + cell - 1) / cell, ch = (image.height() + cell - 1) / cell;
    std::vector<LensLight> grid(std::size_t(cw) * std::size_t(ch));
    std::vector<double> weight(grid.size());
    for (int y = 0; y < image.height(); ++y) {
        const float* row = image.row(y);
        for (int x = 0; x < image.width(); ++x) {
            const float* p = row + 4 * x;
            const double lum = luminance(p[0], p[1], p[2]);
            if (!(lum >= threshold)) continue;
            const std::size_t k = std::size_t(y / cell) * std::size_t(cw) + std::size_t(x / cell);
            LensLight& l = grid[k];
            l.x += lum * (x + 0.5), l.y += lum * (y + 0.5);
            weight[k] += lum;
            // Light is never negative: a resize's ringing in one channel takes none away.
            for (int c = 0; c < 3; ++c) l.energy[std::size_t(c)] += std::max(p[c], 0.f);
        }
    }
    for (std::size_t k = 0; k < grid.size(); ++k) {
        if (weight[k] <= 0) continue;
        LensLight l = grid[k];
        l.x /= weight[k], l.y /= weight[k];
        cells.push_back(l);
    }
    std::sort(cells.begin(), cells.end(), [](const LensLight& a, const LensLight& b) {
        return a.energy[0] + a.energy[1] + a.energy[2] > b.energy[0] + b.energy[1] + b.energy[2];
    });
    if (int(cells.size()) > maxSources) cells.resize(std::size_t(std::max(0, maxSources)));
    return cells;
}

LensLight sourceAt(const Image& image, double x, double y, double radius, double threshold) {
    LensLight l;
    l.x = x, l.y = y;
    const int x0 = pixelIndex(x - radius, 0, image.width()),
              x1 = pixelIndex(x + radius, -1, image.width() - 1);
    const int y0 = pixelIndex(y - radius, 0, image.height()),
              y1 = pixelIndex(y + radius, -1, image.height() - 1);
    for (int py = y0; py <= y1; ++py) {
        for (int px = x0; px <= x1; ++px) {
            const Rgba& p = image.at(px, py);
            if (luminance(p.r, p.g, p.b) >= threshold &&
                std::hypot(px + 0.5 - x, py + 0.5 - y) <= radius)
                l.energy[0] += std::max(p.r, 0.f), l.energy[1] += std::max(p.g, 0.f),
                    l.energy[2] += std::max(p.b, 0.f);
        }
    }
    return l;
}

}  // namespace flarekit
