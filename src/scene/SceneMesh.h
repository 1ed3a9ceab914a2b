// SPDX-License-Identifier: Apache-2.0
// Every object of a scene as one triangle list (position, normal, colour per vertex) for the
// GL renderer: spheres tessellated as latitude-longitude grids, boxes as 12 triangles.
#pragma once

#include <vector>

#include "flarekit/Scene.h"

namespace flarekit {

struct MeshVertex {
    float position[3], normal[3], color[3];
};

//! Sphere tessellation: 64 x 32 quads keep the silhouette within 0.12% of the radius
//! (1 - cos(pi / 64)), under a pixel for a sphere up to ~800 px across.
inline constexpr int kSphereSlices = 64, kSphereStacks = 32;

std::vector<MeshVertex> buildSceneMesh(const Scene& scene);

//! The scene with only its opaque objects (and its ground), as the renderer's depth mesh holds
//! them, and with only its translucent ones (opacity < 1, no ground): the two meshes every GL
//! pass that draws objects builds.
Scene opaqueObjects(const Scene& scene);
Scene translucentObjects(const Scene& scene);

//! A translucent object in buildSceneMesh(translucentObjects(scene)): its vertices, opacity and
//! whether it is closed (a sphere or a box, drawn by its front faces so that it counts once
//! for each ray, as the ray caster counts it).
struct TranslucentRange {
    int first = 0, count = 0;
    float opacity = 1;
    bool closed = false;
};
//! Every object of `translucent` (a translucentObjects() scene) in mesh order.
std::vector<TranslucentRange> translucentRanges(const Scene& translucent);

//! Where each object's vertices sit in buildSceneMesh's list (spheres, then boxes, then
//! triangles, in scene order), with a bounding sphere and, for spheres and boxes, the radius
//! of a ball the object surely contains (0 for triangles), for culling and early-outs.
struct MeshObjectRange {
    int first = 0, count = 0;
    Vec3 centre;
    double boundRadius = 0, solidRadius = 0;
};
std::vector<MeshObjectRange> sceneMeshRanges(const Scene& scene);

}  // namespace flarekit
