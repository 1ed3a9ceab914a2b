// SPDX-License-Identifier: Apache-2.0
#include "scene/SceneMesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace flarekit {

namespace {
void push(std::vector<MeshVertex>& out, Vec3 p, Vec3 n, Vec3 c) {
    out.push_back({{float(p.x), float(p.y), float(p.z)},
                   {float(n.x), float(n.y), float(n.z)},
                   {float(c.x), float(c.y), float(c.z)}});
}

//! The unit sphere's tessellation vertices, computed once (every sphere of every scene scales
//! and moves the same table; the sines and cosines were most of a scene's set-up).
Vec3 unitSphere(int slice, int stack) {
    static const std::vector<Vec3> table = [] {
        std::vector<Vec3> t;
        for (int st = 0; st <= kSphereStacks; ++st) {
            for (int sl = 0; sl <= kSphereSlices; ++sl) {
                const double theta = std::numbers::pi * st / kSphereStacks,
                             phi = 2 * std::numbers::pi * sl / kSphereSlices;
                t.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                             std::sin(theta) * std::sin(phi)});
            }
        }
        return t;
    }();
    return table[std::size_t(stack) * (kSphereSlices + 1) + std::size_t(slice)];
}
//! The scene's triangles and its ground's, in the order both mesh functions walk them.
std::vector<Triangle> allTriangles(const Scene& scene) {
    std::vector<Triangle> all = scene.triangles;
    for (const Triangle& t : groundTriangles(scene)) all.push_back(t);
    return all;
}
}  // namespace

std::vector<MeshVertex> buildSceneMesh(const Scene& scene) {
    const std::vector<Triangle> triangles = allTriangles(scene);
    std::vector<MeshVertex> out;
    // Sized once: growing a vector of a few hundred thousand vertices copies it a dozen times.
    out.reserve(scene.spheres.size() * 6 * kSphereSlices * kSphereStacks + scene.boxes.size() * 36 +
                triangles.size() * 3);
    for (const Sphere& s : scene.spheres) {
        for (int st = 0; st < kSphereStacks; ++st) {
            for (int sl = 0; sl < kSphereSlices; ++sl) {
                const Vec3 a = unitSphere(sl, st), b = unitSphere(sl + 1, st),
                           c = unitSphere(sl + 1, st + 1), d = unitSphere(sl, st + 1);
                for (Vec3 n : {a, b, c, a, c, d}) push(out, s.center + n * s.radius, n, s.color);
            }
        }
    }
    for (const Box& b : scene.boxes) {
        const Vec3 lo = b.min, hi = b.max;
        // Each face: normal axis, sign, and its four corners in order.
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                const double v = side ? hi[axis] : lo[axis];
                const int u1 = (axis + 1) % 3, u2 = (axis + 2) % 3;
                Vec3 corner[4];
                const double uv[4][2] = {
                    {lo[u1], lo[u2]}, {hi[u1], lo[u2]}, {hi[u1], hi[u2]}, {lo[u1], hi[u2]}};
                for (int k = 0; k < 4; ++k) {
                    double p[3];
                    p[axis] = v;
                    p[u1] = uv[k][0];
                    p[u2] = uv[k][1];
                    corner[k] = {p[0], p[1], p[2]};
                }
                double nn[3] = {0, 0, 0};
                nn[axis] = side ? 1 : -1;
                const Vec3 n{nn[0], nn[1], nn[2]};
                // Counter-clockwise seen from outside, as the spheres: culling back faces
                // leaves each closed object's front once (translucent objects rely on it).
                if (side)
                    for (int k : {0, 1, 2, 0, 2, 3}) push(out, corner[k], n, b.color);
                else
                    for (int k : {0, 2, 1, 0, 3, 2}) push(out, corner[k], n, b.color);
            }
        }
    }
    for (const Triangle& t : triangles) {
        const Vec3 c = cross(t.b - t.a, t.c - t.a);
        const Vec3 n = length(c) > 0 ? normalize(c) : Vec3{0, 1, 0};
        push(out, t.a, n, t.color);
        push(out, t.b, n, t.color);
        push(out, t.c, n, t.color);
    }
    return out;
}

Scene opaqueObjects(const Scene& scene) {
    Scene s = scene;
    s.spheres.clear(), s.boxes.clear(), s.triangles.clear();
    for (const Sphere& o : scene.spheres)
        if (o.opacity >= 1) s.spheres.push_back(o);
    for (const Box& o : scene.boxes)
        if (o.opacity >= 1) s.boxes.push_back(o);
    for (const Triangle& o : scene.triangles)
        if (o.opacity >= 1) s.triangles.push_back(o);
    return s;
}

Scene translucentObjects(const Scene& scene) {
    Scene s = scene;
    s.spheres.clear(), s.boxes.clear(), s.triangles.clear(), s.ground.reset();
    for (const Sphere& o : scene.spheres)
        if (o.opacity < 1) s.spheres.push_back(o);
    for (const Box& o : scene.boxes)
        if (o.opacity < 1) s.boxes.push_back(o);
    for (const Triangle& o : scene.triangles)
        if (o.opacity < 1) s.triangles.push_back(o);
    return s;
}

std::vector<MeshObjectRange> sceneMeshRanges(const Scene& scene) {
    std::vector<MeshObjectRange> out;
    int first = 0;
    for (const Sphere& s : scene.spheres) {
        const int count = 6 * kSphereSlices * kSphereStacks;
        // The tessellation lies inside the sphere, its flat facets at least r cos(pi/64) out.
        out.push_back({first, count, s.center, s.radius, s.radius * 0.99});
        first += count;
    }
    for (const Box& b : scene.boxes) {
        const Vec3 half = (b.max - b.min) * 0.5;
        out.push_back({first, 36, b.min + half, length(half), std::min({half.x, half.y, half.z})});
        first += 36;
    }
    for (const Triangle& t : allTriangles(scene)) {
        const Vec3 c = (t.a + t.b + t.c) * (1.0 / 3.0);
        out.push_back(
            {first, 3, c, std::max({length(t.a - c), length(t.b - c), length(t.c - c)}), 0.0});
        first += 3;
    }
    return out;
}

std::vector<TranslucentRange> translucentRanges(const Scene& translucent) {
    const std::vector<MeshObjectRange> ranges = sceneMeshRanges(translucent);
    const std::size_t spheres = translucent.spheres.size(), boxes = translucent.boxes.size();
    std::vector<TranslucentRange> out;
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        const double opacity = i < spheres ? translucent.spheres[i].opacity
                               : i < spheres + boxes
                                   ? translucent.boxes[i - spheres].opacity
                                   : translucent.triangles[i - spheres - boxes].opacity;
        out.push_back({ranges[i].first, ranges[i].count, float(opacity), i < spheres + boxes});
    }
    return out;
}

}  // namespace flarekit
