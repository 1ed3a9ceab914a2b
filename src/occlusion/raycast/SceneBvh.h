// SPDX-License-Identifier: Apache-2.0
// A bounding-volume hierarchy over every object of a scene, for any-hit (shadow-style) rays.
// Built by median splits on the longest axis of the primitive centroids; leaves hold up to
// kLeafSize primitives.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "flarekit/Scene.h"

namespace flarekit {

class SceneBvh {
  public:
    explicit SceneBvh(const Scene& scene);
    //! True when the ray origin + t*dir (t > 0) hits any object.
    bool occluded(Vec3 origin, Vec3 dir) const { return transmittance(origin, dir) < 1.0; }
    //! The share of light the ray keeps between origin and origin + tMax*dir: the product of
    //! 1 - opacity over the objects it meets there (0 at the first opaque one).
    double transmittance(Vec3 origin, Vec3 dir,
                         double tMax = std::numeric_limits<double>::infinity()) const;
    std::size_t primitiveCount() const { return m_prims.size(); }

  private:
    enum class Kind : std::uint8_t { Sphere, Box, Triangle };
    struct Prim {
        Kind kind;
        std::uint32_t index;
        Vec3 lo, hi, centre;
    };
    struct Node {
        Vec3 lo, hi;
        std::uint32_t first, count;  //!< leaf: prims [first, first + count); inner: count == 0
        std::uint32_t right;         //!< inner: right child (left child is this + 1)
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t count);
    bool hitPrim(const Prim& p, Vec3 o, Vec3 d, Vec3 invDir, double tMax) const;
    double opacityOf(const Prim& p) const;

    const Scene& m_scene;
    std::vector<Triangle> m_triangles;  //!< the scene's triangles, then its ground's
    std::vector<Prim> m_prims;
    std::vector<Node> m_nodes;
};

}  // namespace flarekit
