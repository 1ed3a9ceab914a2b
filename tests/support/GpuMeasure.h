// SPDX-License-Identifier: Apache-2.0
// What the accuracy test and the accuracy table share: one GPU method run on one still scene,
// and which scenes are judged against the ray-cast truth.
#pragma once

#include <cmath>
#include <string>

#include "flarekit/Visibility.h"
#include "flarekit/gl/GpuVisibility.h"

namespace flarekit::test {

//! A fresh renderer (no shadows: visibility reads depth only) and method, measured to completion.
inline Result<double> measureGpuCoverage(const std::string& method, const Scene& scene,
                                         int msaa = 1, const std::string& variant = "circle") {
    RenderOptions render;
    render.msaaSamples = msaa;
    render.shadows = false;
    auto renderer = SceneRenderer::create(scene, render);
    if (!renderer) return renderer.error();
    GpuVisibilityOptions options;
    options.textureMaskVariant = variant;
    auto m = createGpuVisibility(method, scene, options);
    if (!m) return m.error();
    return measureStillFrame(**m, *renderer, scene, 8);
}

//! Judged: the disc is fully in frame and at least 100 px in area (a smaller disc is a handful of
//! pixels: no method can be judged on it).
inline bool judgedScene(const Scene& s) {
    const double radiusPx = s.sun.angularRadiusDeg * M_PI / 180 * (s.height / 2.0) /
                            std::tan(s.camera.fovYDeg * M_PI / 360);
    return M_PI * radiusPx * radiusPx >= 100 && sunInFrameFraction(s) >= 1.0;
}

}  // namespace flarekit::test
