// SPDX-License-Identifier: Apache-2.0
// The demo's static world and its camera path (see flarekit/Demo.h for the story).
#pragma once

#include "flarekit/Scene.h"

namespace flarekit::demo {

//! Every object of the world; camera and sun left at their defaults.
Scene buildWorld(int width, int height);
//! The driver's camera `t` of the way (0..1) along the road.
SceneCamera cameraAt(double t);
//! Low (7 degrees) and 17 degrees right of the first straight, so roadside trees on the right
//! cross it 30-50 m ahead of the car.
SceneSun demoSun();

}  // namespace flarekit::demo
