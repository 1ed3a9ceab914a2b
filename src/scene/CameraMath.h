// SPDX-License-Identifier: Apache-2.0
// gluLookAt / gluPerspective matrices (column-major, OpenGL conventions) and the projection of
// directions to pixels, shared by the GL renderer and the CPU code that places the flare.
#pragma once

#include <array>

#include "flarekit/Flare.h"
#include "flarekit/Scene.h"

namespace flarekit {

using Mat4 = std::array<double, 16>;  //!< column-major: m[col * 4 + row]

//! gluLookAt's orthonormal camera basis: right, true up, and forward (the view direction).
struct CameraBasis {
    Vec3 right, up, forward;
};
CameraBasis cameraBasis(const SceneCamera& camera);

Mat4 lookAtMatrix(const SceneCamera& camera);
Mat4 perspectiveMatrix(const SceneCamera& camera, double aspect);
//! glOrtho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane).
Mat4 orthographicMatrix(double halfWidth, double halfHeight, double nearPlane, double farPlane);
Mat4 multiply(const Mat4& a, const Mat4& b);
Mat4 inverse(const Mat4& m);  //!< general 4x4 inverse (cofactors)
std::array<float, 16> toFloat(const Mat4& m);

//! Pixel position (top-left origin, pixel centres at +0.5) of the direction `dir` seen from
//! the camera, as a point at infinity. False when the direction is behind the camera.
bool projectDirection(const Scene& scene, Vec3 dir, Point& pixel);
//! The same for a point in the world.
bool projectPoint(const Scene& scene, Vec3 point, Point& pixel);

}  // namespace flarekit
