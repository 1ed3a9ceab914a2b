// SPDX-License-Identifier: Apache-2.0
// The sprite flare of a scene's sun (GL-free): the flare added to a frame on the CPU, scaled
// by the sun's measured coverage. The GPU path (flarekit/gl/GpuFlare.h) reports the same
// FlaredFrame.
#pragma once

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Scene.h"

namespace flarekit {

struct FlaredFrame {
    bool sunInFront = false;   //!< false when the sun is behind the camera: no flare
    Point sunPixel;            //!< where the sun projects (may be outside the frame)
    float flareIntensity = 0;  //!< coverage x the sun's brightness scale
};

//! The flare's brightness for a fully visible sun, by the energy model of flarekit/Flare.h: the
//! luminance of colour x intensity over the sun's disc on screen (its angular radius against
//! the camera's field of view), in frame-height-squared units, over kReferenceFlux.
float sunFlareScale(const Scene& scene);

//! Adds the preset's flare for the scene's sun, scaled by `coverage` (0..1), to `frame`.
FlaredFrame addSunFlare(Image& frame, const Scene& scene, const Preset& preset, double coverage);

}  // namespace flarekit
