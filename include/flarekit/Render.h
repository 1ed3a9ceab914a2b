// Rendering a scene with OpenGL (headless) and putting the sprite flare on it with the sun's
// measured coverage. A GL context must be current (gl::HeadlessGl) for renderScene.
#pragma once

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Scene.h"
#include "flarekit/Visibility.h"

namespace flarekit {

//! The frame as linear HDR RGBA: sky gradient, the sun disc at infinity (colour x intensity),
//! lit objects. Rendered into RGBA16F with a 32-bit float depth buffer.
Result<Image> renderScene(const Scene& scene);

struct FlaredFrame {
    bool sunInFront = false;  //!< false when the sun is behind the camera: no flare
    Point sunPixel;           //!< where the sun projects (may be outside the frame)
    float flareIntensity = 0; //!< coverage x the sun's brightness scale
};

//! Adds the preset's flare for the scene's sun, scaled by `coverage` (0..1), to `frame`.
FlaredFrame addSunFlare(Image& frame, const Scene& scene, const Preset& preset, double coverage);

}  // namespace flarekit
