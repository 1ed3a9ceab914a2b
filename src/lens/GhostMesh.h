// SPDX-License-Identifier: Apache-2.0
// The traced ghost meshes of `lens render` and what both of its rasterisers (the CPU's and
// OpenGL's) share: how the image sits on the sensor, the masks' soft edge, and which triangles
// are drawn, as what, with which irradiance.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flarekit/Lens.h"
#include "lens/LensTrace.h"

namespace flarekit::lens {

//! How the image sits on the sensor: centred, fitted inside it, `mmPerPixel` square pixels.
struct SensorMap {
    double mmPerPixel = 0, width = 0, height = 0;
    //! Display coordinates: mm from the axis, y up. A camera's image is inverted and the photo
    //! turned upright; the lens is rotationally symmetric, so tracing in display coordinates
    //! is the same 180-degree-turned picture.
    double toMmX(double px) const { return (px - width / 2) * mmPerPixel; }
    double toMmY(double py) const { return (height / 2 - py) * mmPerPixel; }
    double toPxX(double mm) const { return mm / mmPerPixel + width / 2; }
    double toPxY(double mm) const { return height / 2 - mm / mmPerPixel; }
};

//! Vertices sit on a grid of 1/256 pixel, the 8 bits of sub-pixel precision GPUs (Mesa's
//! llvmpipe, NVIDIA's) snap them to: both rasterisers then cover exactly the same pixel centres.
//! Far off-frame vertices (a caustic's fold) are left as they are.
inline constexpr double kSubpixelReach = 65536;  //!< past this a float has no 1/256 steps
inline double snapToSubpixel(double px) {
    return std::fabs(px) < kSubpixelReach ? std::round(px * 256.0) / 256.0 : px;
}

//! The iris and clear-aperture masks soften over this share of the stop radius, so a ghost's
//! polygon edge is antialiased at any mesh resolution.
constexpr double kMaskEdge = 0.015;

//! floor(v) as an int within [lo, hi]: ghost rays can land far outside any frame, where a plain
//! cast would overflow.
inline int pixelIndex(double v, int lo, int hi) {
    return int(std::clamp(std::floor(v), double(lo), double(hi)));
}

inline double edgeMask(double q) {
    return std::clamp((1.0 - q) / kMaskEdge + 0.5, 0.0, 1.0);
}

//! One ghost at one wavelength for one source: the traced grid, in pixels.
struct Mesh {
    int side = 0;
    std::vector<RayResult> rays;     //!< side x side, row-major; x, y in pixels
    std::array<double, 3> weight{};  //!< energy per channel x entrance share of one triangle
    double minY = 0, maxY = 0;       //!< pixel rows the mesh touches
};

//! Below this a contribution is invisible in any output (under a 16-bit sRGB file's smallest
//! step above black, 1 / 65535 / 12.92 linear): a ghost's triangles fainter than that are not
//! drawn. Large defocused ghosts spread over many frames' worth of sensor are mostly this.
constexpr double kInvisible = 1e-6;

//! How a triangle meets a mask (the iris at one crossing, or the clear apertures): the masks
//! are convex and their coordinates vary linearly over a triangle, so three vertices inside
//! (by the edge's width) mean all of it is, three outside one half-plane mean none of it.
enum class Cover { Inside, Outside, Edge };

inline Cover irisCover(const lens::Iris& iris, const RayResult& a, const RayResult& b,
                       const RayResult& c, int k) {
    const std::size_t i = std::size_t(2 * k);
    const double qa = lens::irisRadius(iris, a.stop[i], a.stop[i + 1]);
    const double qb = lens::irisRadius(iris, b.stop[i], b.stop[i + 1]);
    const double qc = lens::irisRadius(iris, c.stop[i], c.stop[i + 1]);
    // Where the shape is convex q's largest value over the triangle is at a vertex; a
    // non-convex rounded iris (few blades, little roundness) is tested per pixel.
    if (iris.convex && std::max({qa, qb, qc}) < 1.0 - kMaskEdge) return Cover::Inside;
    // Outside together: beyond the same edge line (or, for a circle, a shared tangent side is
    // not needed; a whole triangle past the circle's edge is caught per pixel).
    if (iris.blades >= 3 && iris.roundness <= 0) {
        for (int e = 0; e < iris.blades; ++e) {
            const double nx = iris.normals[std::size_t(2 * e)],
                         ny = iris.normals[std::size_t(2 * e + 1)];
            const double limit = iris.cosHalf * (1.0 + kMaskEdge);
            if (a.stop[i] * nx + a.stop[i + 1] * ny > limit &&
                b.stop[i] * nx + b.stop[i + 1] * ny > limit &&
                c.stop[i] * nx + c.stop[i + 1] * ny > limit)
                return Cover::Outside;
        }
    }
    return Cover::Edge;
}

//! Calls f(a, b, c) for each triangle of the mesh: every grid cell is two triangles split
//! along its a-d diagonal, and a cell with one dead ray (total internal reflection, a missed
//! surface) keeps the triangle of its three live ones, so a ghost cut by dead rays has a
//! diagonal edge rather than a staircase of whole cells.
template <class F>
void forEachTriangle(const Mesh& m, F f) {
    const int s = m.side;
    const auto at = [&](int x, int y) -> const RayResult& {
        return m.rays[std::size_t(y) * std::size_t(s) + std::size_t(x)];
    };
    for (int iy = 0; iy + 1 < s; ++iy) {
        for (int ix = 0; ix + 1 < s; ++ix) {
            const RayResult &a = at(ix, iy), &b = at(ix + 1, iy), &c = at(ix, iy + 1),
                            &d = at(ix + 1, iy + 1);
            const int dead = !a.alive + !b.alive + !c.alive + !d.alive;
            if (dead == 0) {
                f(a, b, d);
                f(a, d, c);
            } else if (dead == 1) {
                if (!a.alive) f(b, d, c);
                if (!b.alive) f(a, d, c);
                if (!c.alive) f(a, b, d);
                if (!d.alive) f(a, b, c);
            }
        }
    }
}

//! How a triangle of a mesh is drawn: not at all (culled: invisible, or wholly outside a
//! mask), as a point at its centroid (smaller than a pixel: it may cover no pixel centre, so
//! its whole energy goes to the pixel under its centroid), or rasterised with `density`, the
//! triangle's share of the entrance over its area on the sensor (pixels).
struct TrianglePlan {
    bool draw = false, point = false;
    double density = 0;
};
TrianglePlan planTriangle(const Mesh& m, const Iris& iris, const RayResult& a, const RayResult& b,
                          const RayResult& c);

//! The triangle (a, b, c) cut to the image rectangle [0, width] x [0, height] (Sutherland and
//! Hodgman), as a fan of triangles whose new vertices carry the linearly interpolated
//! attributes and sit on the sub-pixel grid: both rasterisers draw exactly these pieces, so
//! OpenGL never clips (its clipper would place new vertices its own way). A triangle inside
//! the image is itself; one outside, nothing.
//! Whether the triangle lies within [0, width] x [0, height] (no clipping needed).
inline bool insideImage(const RayResult& a, const RayResult& b, const RayResult& c, int width,
                        int height) {
    return std::min({a.x, b.x, c.x}) >= 0 && std::max({a.x, b.x, c.x}) <= width &&
           std::min({a.y, b.y, c.y}) >= 0 && std::max({a.y, b.y, c.y}) <= height;
}
std::vector<std::array<RayResult, 3>> clipToImage(const RayResult& a, const RayResult& b,
                                                  const RayResult& c, int width, int height);

//! Where the ghost meshes of each light go: the CPU rasteriser, or OpenGL's.
class GhostDrawer {
  public:
    virtual ~GhostDrawer() = default;
    //! Adds every triangle of `meshes` (one light's ghosts at every wavelength).
    virtual Status draw(const std::vector<Mesh>& meshes, const Iris& iris) = 0;
    //! The sum of everything drawn, into `ghosts` (RGB; alpha is set by the caller).
    virtual Status finish(Image& ghosts) = 0;
};

//! renderLensFlare with the ghosts rasterised by `drawer`; the starburst and glare are the
//! CPU's in every case.
Result<LensFlareLayers> renderLensFlareWith(const Lens& lens, int width, int height,
                                            const std::vector<LensLight>& lights,
                                            const LensRenderOptions& options, GhostDrawer& drawer);

}  // namespace flarekit::lens
