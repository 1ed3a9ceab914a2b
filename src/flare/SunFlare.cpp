// The sprite flare on a scene's sun, on the CPU: where the sun projects and how bright its
// flare is for a given coverage.
#include "flarekit/SunFlare.h"

#include "flarekit/Color.h"
#include "scene/CameraMath.h"

namespace flarekit {

float sunFlareScale(const SceneSun& sun) {
    const Vec3 radiance = sun.color * sun.intensity;
    return flareScaleForBrightness(
        luminance(float(radiance.x), float(radiance.y), float(radiance.z)));
}

FlaredFrame addSunFlare(Image& frame, const Scene& scene, const Preset& preset, double coverage) {
    FlaredFrame result;
    result.sunInFront = projectDirection(scene, scene.sun.direction, result.sunPixel);
    if (!result.sunInFront || coverage <= 0) return result;
    result.flareIntensity = float(coverage) * sunFlareScale(scene.sun);
    renderFlare(frame, preset, result.sunPixel, result.flareIntensity);
    return result;
}

}  // namespace flarekit
