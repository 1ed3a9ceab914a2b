// SPDX-License-Identifier: Apache-2.0
// The built-in demo: a drive along a road lined with trees, past buildings, through a tunnel
// and into a left turn, with a low sun ahead on the right that flickers through the foliage,
// vanishes in the tunnel and leaves the frame in the turn (the seeds' racing-game setting).
#pragma once

#include <memory>
#include <string>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Scene.h"
#include "flarekit/Temporal.h"

namespace flarekit {

//! The drive takes 8 s: 231 m at 28.9 m/s (104 km/h). Frame i shows time i / fps, so
//! --frames 240 at 30 fps is the whole drive and fewer frames a shorter one, at the same speed;
//! frames past the 8 s hold the drive's last position.
inline constexpr double kDemoDurationSeconds = 8.0;

//! The demo world with the camera at `t` (0 = start, 1 = end of the drive).
Scene demoScene(int width, int height, double t);

struct DemoSettings {
    int width = 1280, height = 720;
    int frames = 240;
    double fps = 30.0;               //!< frames per second of drive time (and of the MP4)
    std::string method = "raycast";  //!< visibility method
    int raycastSamplesPerSide = 64;  //!< 4096 rays a frame; the temporal filter absorbs the noise
    int msaaSamples = 1;
    //! `query` only: the flare's draws are conditional on the sun's occlusion query
    //! (glBeginConditionalRender), so the GPU skips them when the sun is hidden.
    bool conditionalRender = false;
    TemporalParams temporal;
    //! Read back the GPU method's working textures with every frame (DemoFrame's methodViews:
    //! the studio's diagnostic panels); a wait per frame.
    bool methodViews = false;
};
inline constexpr Param<DemoSettings> kDemoParams[] = {
    param<&DemoSettings::frames>("frames", 1, 100000, "",
                                 "frames from the start of the 8 s drive, at --fps (240 at 30 fps: "
                                 "the whole drive; fewer: a shorter one)"),
    param<&DemoSettings::fps>("fps", 1, 240, "frames/s", "frame rate of the drive and its MP4"),
    param<&DemoSettings::raycastSamplesPerSide>("samples", 1, 4096, "",
                                                "raycast: strata per side (N^2 rays a frame)"),
    oneOf<&DemoSettings::msaaSamples>("msaa", kMsaaSampleCounts, "samples",
                                      "samples per pixel for the scene pass"),
    param<&DemoSettings::width>("width", 16, 16384, "pixels", "frame width"),
    param<&DemoSettings::height>("height", 16, 16384, "pixels", "frame height"),
};

//! Range checks of every setting (no GL needed); errors name the setting.
Status validateDemoSettings(const DemoSettings& settings);

}  // namespace flarekit
