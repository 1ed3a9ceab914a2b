// SPDX-License-Identifier: Apache-2.0
// Exact ray-primitive tests for occlusion: each answers whether the ray origin + t*dir hits
// the primitive for some t > kMinT. Directions need not be unit length.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "flarekit/Scene.h"

namespace flarekit::intersect {

//! Hits closer than this (in scene units) are ignored, so a camera resting on a surface is not
//! occluded by it through rounding.
inline constexpr double kMinT = 1e-9;

//! Whether the segment (kMinT, tMax) of the ray meets the solid ball.
inline bool sphere(Vec3 o, Vec3 d, const Sphere& s,
                   double tMax = std::numeric_limits<double>::infinity()) {
    const Vec3 oc = o - s.center;
    const double a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius;
    const double disc = b * b - a * c;
    if (disc < 0) return false;
    const double root = std::sqrt(disc);
    // The far hit is ahead (the near one is, or the camera is inside) and the near one comes
    // before tMax.
    return (-b + root) / a > kMinT && (-b - root) / a < tMax;
}

//! Slab test against [lo, hi]; invDir = 1/dir per component (infinities allowed).
inline bool slabs(Vec3 o, Vec3 invDir, Vec3 lo, Vec3 hi,
                  double tMax = std::numeric_limits<double>::infinity()) {
    double t0 = kMinT, t1 = tMax;
    for (int i = 0; i < 3; ++i) {
        double a = (lo[i] - o[i]) * invDir[i], b = (hi[i] - o[i]) * invDir[i];
        if (std::isnan(a) || std::isnan(b)) {  // 0 * inf: ray parallel to and on the slab plane
            if (o[i] < lo[i] || o[i] > hi[i]) return false;
            continue;
        }
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

//! Möller-Trumbore, double-sided; hits in (kMinT, tMax).
inline bool triangle(Vec3 o, Vec3 d, const Triangle& tri,
                     double tMax = std::numeric_limits<double>::infinity()) {
    const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const double inv = 1.0 / det;
    const Vec3 s = o - tri.a;
    const double u = dot(s, p) * inv;
    if (u < 0 || u > 1) return false;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) * inv;
    if (v < 0 || u + v > 1) return false;
    const double t = dot(e2, q) * inv;
    return t > kMinT && t < tMax;
}

}  // namespace flarekit::intersect
