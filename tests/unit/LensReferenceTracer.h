// SPDX-License-Identifier: Apache-2.0
// A second sequential ray tracer for the ghost tests, written apart from src/lens/LensTrace.cpp
// and sharing none of its code: the surfaces in the textbook vertex-plane form (transfer to the
// vertex plane, then the closed-form step to the sphere, Welford's "Aberrations of Optical
// Systems", 1986, section 4.4), Snell's law as n' d' = n d + (n' cos' - n cos) N, the media by
// the path's legs, the iris by its vertices, its own beam on a plane across the rays and its own
// random numbers. d line only (n = n_d exactly there): it checks positions and shares, not
// colours.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "flarekit/Lens.h"

namespace reference {

struct V3 {
    double x = 0, y = 0, z = 0;
};
inline V3 operator+(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V3 operator*(double k, V3 a) {
    return {k * a.x, k * a.y, k * a.z};
}
inline double dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

//! Whether stop-plane point (x, y), in units of the stop's radius, is inside the iris: the
//! polygon through its vertices, each blade bowed out by `roundness` toward the unit circle
//! (the boundary's radius at angle phi is (1 - roundness) P(phi) + roundness, P the polygon's).
inline bool insideIris(const flarekit::LensAperture& a, double x, double y) {
    const double r = std::hypot(x, y);
    if (a.blades < 3 || a.roundness >= 1) return r <= 1;
    const int n = std::min(a.blades, 32);
    const double rot = a.rotationDeg * M_PI / 180, step = 2 * M_PI / n;
    // The edge the direction (x, y) meets: between the vertices either side of its angle.
    double phi = std::atan2(y, x) - rot;
    phi -= 2 * M_PI * std::floor(phi / (2 * M_PI));
    const int k = std::min(n - 1, int(phi / step));
    const double ax = std::cos(rot + k * step), ay = std::sin(rot + k * step);
    const double bx = std::cos(rot + (k + 1) * step), by = std::sin(rot + (k + 1) * step);
    if (r == 0) return true;
    // The ray s (x, y) / r meets the chord a + t (b - a) where the 2-D cross products agree.
    const double ux = x / r, uy = y / r;
    const double ex = bx - ax, ey = by - ay;
    const double s = (ax * ey - ay * ex) / (ux * ey - uy * ex);
    return r <= (1 - a.roundness) * s + a.roundness;
}

struct Result {
    bool arrived = false;
    double x = 0, y = 0;
    //! Refracted on the backward leg while moving toward +z (a steep ray in a curved gap).
    bool steepBackwardLeg = false;
};

//! Which side of a refracting surface the ray comes from: by the path's legs (right), or by the
//! sign of d.z (the rule flarekit's tracer used before, kept to show the tests can tell).
enum class Media { ByLeg, ByDirectionSign };

class Tracer {
  public:
    explicit Tracer(const flarekit::Lens& lens, Media media = Media::ByLeg)
        : m_lens(lens), m_media(media) {
        double z = 0;
        for (const flarekit::LensSurface& s : lens.surfaces) {
            m_vertex.push_back(z);
            z += s.thickness;
        }
        m_sensorZ = z;
    }

    //! Index before surface k (travelling +z) and after it.
    double before(int k) const { return k == 0 ? 1.0 : m_lens.surfaces[std::size_t(k - 1)].nd; }
    double after(int k) const { return m_lens.surfaces[std::size_t(k)].nd; }

    //! The ray (p, d) through the ghost reflecting at `first`, then `second` (-1: direct).
    Result trace(V3 p, V3 d, int first, int second) const {
        const int count = int(m_lens.surfaces.size());
        std::vector<std::pair<int, bool>> steps;  // surface, reflects
        if (first < 0) {
            for (int k = 0; k < count; ++k) steps.push_back({k, false});
        } else {
            for (int k = 0; k <= first; ++k) steps.push_back({k, k == first});
            for (int k = first - 1; k >= second; --k) steps.push_back({k, k == second});
            for (int k = second + 1; k < count; ++k) steps.push_back({k, false});
        }
        bool forward = true, steep = false;
        for (const auto& [k, reflects] : steps) {
            const flarekit::LensSurface& s = m_lens.surfaces[std::size_t(k)];
            const double c = s.radius == 0 ? 0 : 1 / s.radius;
            // Transfer to the vertex plane, then along the ray to the sphere.
            if (d.z == 0) return {};
            const double t0 = (m_vertex[std::size_t(k)] - p.z) / d.z;
            V3 q = p + t0 * d;
            const double delta = capStep(q, d, c, t0);
            if (std::isnan(delta)) return {};
            q = q + delta * d;
            const double local = q.z - m_vertex[std::size_t(k)];
            if (s.stop) {
                if (!insideIris(m_lens.aperture, q.x / s.semiAperture, q.y / s.semiAperture))
                    return {};
            } else if (std::hypot(q.x, q.y) > s.semiAperture) {
                return {};
            }
            // The unit normal of c (x^2 + y^2 + z^2) - 2 z = 0, turned along the ray (into the
            // medium it goes on to).
            V3 normal{-c * q.x, -c * q.y, 1 - c * local};
            double cosIn = dot(normal, d);
            if (cosIn < 0) normal = -1.0 * normal, cosIn = -cosIn;
            if (reflects) {
                d = d + (-2 * cosIn) * normal;
                forward = !forward;
            } else {
                steep = steep || (!forward && d.z > 0);
                const bool front = m_media == Media::ByLeg ? forward : d.z > 0;
                const double n0 = front ? before(k) : after(k);
                const double n1 = front ? after(k) : before(k);
                const double sin2 = (n0 / n1) * (n0 / n1) * (1 - cosIn * cosIn);
                if (sin2 > 1) return {};
                const double cosOut = std::sqrt(1 - sin2);
                d = (n0 / n1) * d + ((cosOut - (n0 / n1) * cosIn)) * normal;
            }
            p = q;
        }
        if (d.z <= 0) return {};
        const double t = (m_sensorZ - p.z) / d.z;
        return {true, p.x + t * d.x, p.y + t * d.y, steep};
    }

    //! From the point q where the ray d meets the vertex plane (t0 along it from its start), the
    //! step to the sphere of curvature c: the roots of c s^2 - 2 b s + h = 0 in the stable
    //! product form, of which the first ahead of the start that lies on the vertex's hemisphere
    //! (the normal's z part 1 - c z > 0). A nearly transverse ray can cross the cap twice; it
    //! meets the first crossing. NaN: it misses.
    static double capStep(V3 q, V3 d, double c, double t0) {
        const double b = d.z - c * (q.x * d.x + q.y * d.y), h = c * (q.x * q.x + q.y * q.y);
        if (c == 0) return t0 > 1e-9 ? 0.0 : std::nan("");
        const double disc = b * b - c * h;
        if (disc < 0) return std::nan("");
        const double big = b + std::copysign(std::sqrt(disc), b);
        double roots[2] = {big == 0 ? 0 : h / big, big / c};
        if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
        for (const double step : roots) {
            const double z = step * d.z;  // from the vertex plane
            if (t0 + step > 1e-9 && 1 - c * z > 0) return step;
        }
        return std::nan("");
    }

    //! Whether the ray meets the first surface inside its clear aperture.
    bool enters(V3 p, V3 d) const {
        const flarekit::LensSurface& s = m_lens.surfaces.front();
        const double c = s.radius == 0 ? 0 : 1 / s.radius;
        const double t0 = -p.z / d.z;
        const V3 q = p + t0 * d;
        const double step = capStep(q, d, c, t0);
        if (std::isnan(step)) return false;
        const V3 hit = q + step * d;
        return std::hypot(hit.x, hit.y) <= s.semiAperture;
    }

  private:
    const flarekit::Lens& m_lens;
    Media m_media;
    std::vector<double> m_vertex;
    double m_sensorZ = 0;
};

//! One ghost as the reference sees it.
struct Figure {
    double share = 0;                 //!< arriving rays over entering rays
    double centerX = 0, centerY = 0;  //!< centroid of the rays landing on the sensor
    double landed = 0;                //!< landing rays over arriving rays
    double radius90 = 0;              //!< around that centroid, holding 90% of the landing rays
    double steep = 0;  //!< landing rays refracted on the backward leg while moving toward +z
    long arrived = 0;
};

//! The parallel beam of field angle (X, Y) degrees from a square across the rays, in front of
//! the lens, wide enough for the whole first surface seen obliquely. Cells within two of one
//! holding an arriving ray of a first `side` x `side` pass are traced again at k x k random
//! points, k chosen for about `target` arriving rays; a path whose first-pass share is under
//! `refineFrom`, or (with a refineFrom) under 40% of whose rays land, gets its shares alone.
inline Figure measure(const flarekit::Lens& lens, double angleXDeg, double angleYDeg, int first,
                      int second, int side, long target, double refineFrom = 0,
                      Media media = Media::ByLeg) {
    const Tracer tracer(lens, media);
    V3 d{std::tan(angleXDeg * M_PI / 180), std::tan(angleYDeg * M_PI / 180), 1};
    d = (1 / std::sqrt(dot(d, d))) * d;
    // An orthonormal pair across the beam.
    V3 e1{d.z, 0, -d.x};
    e1 = (1 / std::sqrt(dot(e1, e1))) * e1;
    const V3 e2{d.y * e1.z - d.z * e1.y, d.z * e1.x - d.x * e1.z, d.x * e1.y - d.y * e1.x};
    const flarekit::LensSurface& s0 = lens.surfaces.front();
    // The rim's depth from the vertex plane, and a plane across the beam well in front of the
    // surface through the axis: the rim seen along the beam lies within `half` of its centre.
    const double r0 = s0.radius, a0 = s0.semiAperture;
    const double rim = r0 == 0 ? 0.0 : std::fabs(r0) - std::sqrt(r0 * r0 - a0 * a0);
    const double z0 = -(rim + 10);
    const V3 centre = (z0 / d.z) * d;
    const double half = a0 * 1.02 + (rim + std::fabs(z0)) * std::sqrt(1 - d.z * d.z);
    const double cell = 2 * half / side;
    const auto origin = [&](double u, double v) { return centre + u * e1 + v * e2; };
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<char> hit(std::size_t(side) * std::size_t(side), 0);
    long entering = 0, arrivedCoarse = 0, landedCoarse = 0;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const V3 o =
                origin(-half + (i + uniform(random)) * cell, -half + (j + uniform(random)) * cell);
            if (!tracer.enters(o, d)) continue;
            ++entering;
            const Result r = tracer.trace(o, d, first, second);
            if (!r.arrived) continue;
            hit[std::size_t(j * side + i)] = 1, ++arrivedCoarse;
            landedCoarse +=
                std::fabs(r.x) <= lens.sensor.width / 2 && std::fabs(r.y) <= lens.sensor.height / 2;
        }
    }
    Figure f;
    if (arrivedCoarse == 0 || entering == 0) return f;
    // Below `refineFrom`, or mostly off the sensor (under 40% landing: not a ghost the tests
    // compare), the first pass's share is all the caller needs.
    if (double(arrivedCoarse) < refineFrom * double(entering) ||
        (refineFrom > 0 && double(landedCoarse) < 0.4 * double(arrivedCoarse))) {
        f.share = double(arrivedCoarse) / double(entering);
        f.landed = double(landedCoarse) / double(arrivedCoarse);
        f.arrived = arrivedCoarse;
        return f;
    }
    const int k = std::max(
        1, std::min(48, int(std::ceil(std::sqrt(double(target) / double(arrivedCoarse))))));
    std::vector<std::array<double, 2>> landed;
    long steep = 0;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            bool near = false;
            for (int y = std::max(0, j - 2); y <= std::min(side - 1, j + 2); ++y)
                for (int x = std::max(0, i - 2); x <= std::min(side - 1, i + 2); ++x)
                    near = near || hit[std::size_t(y * side + x)];
            if (!near) continue;
            for (int b = 0; b < k; ++b) {
                for (int a = 0; a < k; ++a) {
                    const V3 o = origin(-half + (i + (a + uniform(random)) / k) * cell,
                                        -half + (j + (b + uniform(random)) / k) * cell);
                    if (!tracer.enters(o, d)) continue;
                    const Result r = tracer.trace(o, d, first, second);
                    if (!r.arrived) continue;
                    ++f.arrived;
                    if (std::fabs(r.x) <= lens.sensor.width / 2 &&
                        std::fabs(r.y) <= lens.sensor.height / 2) {
                        landed.push_back({r.x, r.y});
                        steep += r.steepBackwardLeg;
                    }
                }
            }
        }
    }
    f.share = double(f.arrived) / (double(entering) * k * k);
    if (landed.empty()) return f;
    f.landed = double(landed.size()) / double(f.arrived);
    f.steep = double(steep) / double(landed.size());
    for (const auto& l : landed) f.centerX += l[0], f.centerY += l[1];
    f.centerX /= double(landed.size()), f.centerY /= double(landed.size());
    std::vector<double> radii;
    for (const auto& l : landed) radii.push_back(std::hypot(l[0] - f.centerX, l[1] - f.centerY));
    std::sort(radii.begin(), radii.end());
    f.radius90 = radii[std::min(radii.size() - 1, std::size_t(0.9 * double(radii.size())))];
    return f;
}

}  // namespace reference
