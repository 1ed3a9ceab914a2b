// SPDX-License-Identifier: Apache-2.0
// The sprite flare on a scene's sun, on the CPU: where the sun projects and how bright its
// flare is for a given coverage.
#include "flarekit/SunFlare.h"

#include <cmath>
#include <numbers>

#include "flarekit/Color.h"
#include "scene/CameraMath.h"

namespace flarekit {

float sunFlareScale(const Scene& scene) {
    const Vec3 radiance = scene.sun.color * scene.sun.intensity;
    // The sun's disc on screen: its angular radius over the half field of view, in frame
    // heights, so its flux in H^2 units is luminance x pi x (that radius)^2.
    constexpr double pi = std::numbers::pi;
    const double toRad = pi / 180.0;
    const double radiusOfHeight = std::tan(scene.sun.angularRadiusDeg * toRad) /
                                  (2.0 * std::tan(0.5 * scene.camera.fovYDeg * toRad));
    const double flux = double(luminance(float(radiance.x), float(radiance.y), float(radiance.z))) *
                        pi * radiusOfHeight * radiusOfHeight;
    return float(flux / kReferenceFlux);
}

FlaredFrame addSunFlare(Image& frame, const Scene& scene, const Preset& preset, double coverage) {
    FlaredFrame result;
    result.sunInFront = projectDirection(scene, scene.sun.direction, result.sunPixel);
    if (!result.sunInFront || coverage <= 0) return result;
    result.flareIntensity = float(coverage) * sunFlareScale(scene);
    renderFlare(frame, preset, result.sunPixel, result.flareIntensity);
    return result;
}

}  // namespace flarekit
