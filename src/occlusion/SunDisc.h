// SPDX-License-Identifier: Apache-2.0
// The sun's projected disc in a frame: the CPU half of shaders/sun_disc.glsl (the two read the
// same line for line), its pixel bounding box, and the uniforms that hand it to a shader.
#pragma once

#include <epoxy/gl.h>

#include "flarekit/Scene.h"

namespace flarekit::occlusion {

struct SunDiscView {
    Vec3 right, up, forward;  //!< gluLookAt basis of the camera
    double tanHalfX = 1, tanHalfY = 1;
    int width = 1, height = 1;  //!< frame size in pixels
    Vec3 sun;                   //!< unit direction toward the sun
    double chord2 = 0;          //!< 2 (1 - cos(angular radius))
    //! The light's own stored depth (classic [0, 1] depth of the camera's projection): 1, the
    //! cleared far value, for a light at infinity; a sphere light's near side, pulled 0.1%
    //! toward the camera, otherwise. A pixel sees the light where its depth is at least this.
    double lightDepth = 1.0;
    //! GL pixel box [x0, x1) x [y0, y1) (origin bottom-left) holding the disc's in-frame part;
    //! empty when none of it is in the frame.
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    //! The rim's projected extent before clamping (GL pixels); valid when `bounded`.
    double rimX0 = 0, rimY0 = 0, rimX1 = 0, rimY1 = 0;
    bool bounded = false;
};

//! The disc as seen by `camera` over a width x height frame with vertical field of view fovYDeg.
SunDiscView sunDiscView(const SceneCamera& camera, int width, int height, const SceneSun& sun);
inline SunDiscView sunDiscView(const Scene& s) {
    return sunDiscView(s.camera, s.width, s.height, s.sun);
}

Vec3 rayThrough(const SunDiscView& v, double px, double py);
bool inSunDisc(const SunDiscView& v, Vec3 d);
//! Area share inside the disc (4 x 4 sub-samples) x cos^3 of the pixel centre's angle.
double discWeight(const SunDiscView& v, int x, int y);

//! Sets the sun_disc.glsl uniforms of `program`.
void setSunDiscUniforms(GLuint program, const SunDiscView& v);

}  // namespace flarekit::occlusion
