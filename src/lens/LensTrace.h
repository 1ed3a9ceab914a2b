// SPDX-License-Identifier: Apache-2.0
// The exact sequential tracer: real spheres, vector Snell refraction, Fresnel and coating
// weights at every interface, the clear aperture of every surface and the iris polygon at the
// stop. One wavelength per prepared lens. Shared by the ghost analysis and the renderer.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flarekit/Lens.h"

namespace flarekit::lens {

struct Vec {
    double x = 0, y = 0, z = 0;
};

//! The iris polygon, ready to test points against: its edges' outward normals.
struct Iris {
    int blades = 0;      //!< < 3: a circle
    double cosHalf = 1;  //!< cos(pi / blades): the inscribed polygon's edge distance
    double roundness = 0;
    std::array<double, 64> normals{};  //!< (x, y) per edge
    //! Whether the shape is convex, so q's largest value over a triangle is at a vertex.
    bool convex = true;
};
Iris makeIris(const LensAperture& aperture);
//! q <= 1 inside the iris at normalised stop coordinates (q = r / the edge's radius there).
double irisRadius(const Iris& iris, double x, double y);

//! The sag of a sphere of radius r (0: flat) at height h from the axis: how far the surface
//! lies behind its vertex there. Heights past |r| are clamped to the sphere's rim.
inline double surfaceSag(double r, double h) {
    if (r == 0.0) return 0.0;
    return r - std::copysign(std::sqrt(std::max(0.0, r * r - h * h)), r);
}

struct TraceSurface {
    double z = 0;       //!< vertex position on the axis
    double radius = 0;  //!< 0: flat
    double semiAperture = 0;
    double nAfter = 1;  //!< index after the surface at this wavelength
    bool stop = false;
    LensCoating coating;
    //! interfaceReflectance against the incidence cosine, kReflectanceSteps + 1 samples, for
    //! light arriving from the front (travelling +z) and from the back: the complex thin-film
    //! sum is too dear to evaluate per ray.
    std::vector<float> reflectFromFront, reflectFromBack;
};
inline constexpr int kReflectanceSteps = 2048;

//! A lens at one wavelength, ready to trace.
struct TraceLens {
    std::vector<TraceSurface> surfaces;
    double sensorZ = 0;
    double lambdaNm = 587.56;
    LensAperture aperture;
    Iris iris;
    double nBefore(std::size_t i) const { return i == 0 ? 1.0 : surfaces[i - 1].nAfter; }
};
TraceLens prepareTrace(const Lens& lens, double lambdaNm);

//! One interaction of a path: refract through `surface`, or reflect off it.
struct PathStep {
    int surface = 0;
    bool reflect = false;
};
//! The direct path (first = second = -1) or the ghost reflecting at `first`, then at `second`.
std::vector<PathStep> ghostPath(int surfaceCount, int first, int second);

//! Whether the surface can reflect at all (an index step or a coating) and is not the stop.
bool canReflect(const TraceLens& lens, int surface);

//! The largest number of stop crossings a two-reflection path has (forward, back, forward).
inline constexpr int kMaxStopCrossings = 3;

struct RayResult {
    bool alive = false;     //!< reached the sensor plane (no miss, no total reflection)
    double x = 0, y = 0;    //!< sensor-plane position, mm
    double throughput = 0;  //!< product of the Fresnel/coating factors along the path
    //! Where the ray crossed the stop, in units of the stop's radius, once per crossing.
    std::array<double, 2 * kMaxStopCrossings> stop{};
    int stopCrossings = 0;
    //! The largest r / semi-aperture over every other surface the path meets: > 1 = vignetted.
    double vignette = 0;
};

//! Traces one ray along `path`. With `clip`, a ray past a clear aperture or outside the iris is
//! dead; without, it continues (the renderer masks per pixel from `stop` and `vignette`).
//! `points`, when given, receives the ray's start, every surface it meets and its sensor hit
//! (the cross-section drawing of `lens sheet`).
RayResult traceRay(const TraceLens& lens, const std::vector<PathStep>& path, Vec origin, Vec dir,
                   bool clip, std::vector<Vec>* points = nullptr);

//! irisRadius of the aperture (builds the iris on each call; for one-off tests of a point).
double apertureRadius(const LensAperture& aperture, double x, double y);

//! The parallel beam of a field angle: direction (tan X, tan Y, 1) normalised, and the origin of
//! the ray through (x, y) on the first surface's vertex plane, started in front of the lens.
//! Whether the ray meets the first surface inside its clear aperture (the light that enters).
bool entersLens(const TraceLens& lens, Vec origin, Vec dir);

Vec beamDirection(double angleXDeg, double angleYDeg);
Vec beamOrigin(const TraceLens& lens, Vec dir, double x, double y);

//! The parallel beam `dir` over a grid of `gridSide` cells per clear diameter on the first
//! surface's vertex plane, widened by beamMargin so that it holds all the light entering the
//! first surface. One ray at a fixed random place in each cell (stratified jitter, the same for
//! every wavelength and call): a regular grid's rows line up with the iris's flat edges and
//! bias compact ghosts.
struct Beam {
    Vec dir;
    double semiAperture = 0, spacing = 0;
    int margin = 0, cellsPerSide = 0;
    std::vector<Vec> origins;  //!< the rays that enter the first surface's clear aperture
    std::vector<int> cells;    //!< the grid cell of each origin, row-major
    //! The origin of the point (fx, fy) in [0, 1)^2 of grid cell `cell`.
    Vec origin(const TraceLens& lens, int cell, double fx, double fy) const;
};
Beam makeBeam(const TraceLens& lens, Vec dir, int gridSide);

//! Grid steps of `spacing` to add on every side of the square [-sa, sa]^2 on the first
//! surface's vertex plane so that the grid holds every ray of the oblique beam `dir` that
//! enters the clear aperture: a curved first surface's rim lies sag(sa) from the vertex plane,
//! and the rays entering there cross that plane sag tan(angle) further out.
int beamMargin(const TraceLens& lens, Vec dir, double spacing);

}  // namespace flarekit::lens
