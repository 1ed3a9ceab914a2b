// SPDX-License-Identifier: Apache-2.0
#include "occlusion/raycast/SceneBvh.h"

#include <algorithm>

#include "occlusion/raycast/Intersect.h"

namespace flarekit {

namespace {
constexpr std::uint32_t kLeafSize = 4;  //!< primitives per leaf: cheap tests, shallow tree
Vec3 vmin(Vec3 a, Vec3 b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
Vec3 vmax(Vec3 a, Vec3 b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
}  // namespace

SceneBvh::SceneBvh(const Scene& scene) : m_scene(scene), m_triangles(scene.triangles) {
    for (const Triangle& t : groundTriangles(scene)) m_triangles.push_back(t);
    for (std::uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const Vec3 r{s.radius, s.radius, s.radius};
        m_prims.push_back({Kind::Sphere, i, s.center - r, s.center + r, s.center});
    }
    for (std::uint32_t i = 0; i < scene.boxes.size(); ++i) {
        const Box& b = scene.boxes[i];
        m_prims.push_back({Kind::Box, i, b.min, b.max, 0.5 * (b.min + b.max)});
    }
    for (std::uint32_t i = 0; i < m_triangles.size(); ++i) {
        const Triangle& t = m_triangles[i];
        const Vec3 lo = vmin(t.a, vmin(t.b, t.c)), hi = vmax(t.a, vmax(t.b, t.c));
        m_prims.push_back({Kind::Triangle, i, lo, hi, 0.5 * (lo + hi)});
    }
    m_nodes.reserve(2 * m_prims.size() / kLeafSize + 2);
    if (!m_prims.empty()) build(0, std::uint32_t(m_prims.size()));
}

std::uint32_t SceneBvh::build(std::uint32_t first, std::uint32_t count) {
    const std::uint32_t at = std::uint32_t(m_nodes.size());
    m_nodes.push_back({});
    Vec3 lo = m_prims[first].lo, hi = m_prims[first].hi, clo = m_prims[first].centre, chi = clo;
    for (std::uint32_t i = first; i < first + count; ++i) {
        lo = vmin(lo, m_prims[i].lo);
        hi = vmax(hi, m_prims[i].hi);
        clo = vmin(clo, m_prims[i].centre);
        chi = vmax(chi, m_prims[i].centre);
    }
    const Vec3 extent = chi - clo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    if (count <= kLeafSize || extent[axis] <= 0) {
        m_nodes[at] = {lo, hi, first, count, 0};
        return at;
    }
    const std::uint32_t half = count / 2;
    std::nth_element(
        m_prims.begin() + first, m_prims.begin() + first + half, m_prims.begin() + first + count,
        [axis](const Prim& a, const Prim& b) { return a.centre[axis] < b.centre[axis]; });
    build(first, half);
    const std::uint32_t right = build(first + half, count - half);
    m_nodes[at] = {lo, hi, first, 0, right};
    return at;
}

bool SceneBvh::hitPrim(const Prim& p, Vec3 o, Vec3 d, Vec3 invDir, double tMax) const {
    switch (p.kind) {
        case Kind::Sphere:
            return intersect::sphere(o, d, m_scene.spheres[p.index], tMax);
        case Kind::Box:
            return intersect::slabs(o, invDir, m_scene.boxes[p.index].min,
                                    m_scene.boxes[p.index].max, tMax);
        case Kind::Triangle:
            return intersect::triangle(o, d, m_triangles[p.index], tMax);
    }
    return false;
}

double SceneBvh::opacityOf(const Prim& p) const {
    switch (p.kind) {
        case Kind::Sphere:
            return m_scene.spheres[p.index].opacity;
        case Kind::Box:
            return m_scene.boxes[p.index].opacity;
        case Kind::Triangle:
            return m_triangles[p.index].opacity;
    }
    return 1.0;
}

double SceneBvh::transmittance(Vec3 o, Vec3 d, double tMax) const {
    if (m_nodes.empty()) return 1.0;
    const Vec3 invDir{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    double kept = 1.0;
    while (top > 0) {
        const Node& n = m_nodes[stack[--top]];
        if (!intersect::slabs(o, invDir, n.lo, n.hi, tMax)) continue;
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                if (!hitPrim(m_prims[i], o, d, invDir, tMax)) continue;
                kept *= 1.0 - opacityOf(m_prims[i]);
                if (kept <= 0.0) return 0.0;  // an opaque object: nothing gets through
            }
        } else {
            stack[top++] = n.right;
            stack[top++] = std::uint32_t(&n - m_nodes.data()) + 1;
        }
    }
    return kept;
}

}  // namespace flarekit
