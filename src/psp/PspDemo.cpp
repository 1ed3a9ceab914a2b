// SPDX-License-Identifier: Apache-2.0
// The demo drive through the emulator: each frame's occluder mask is the demo world ray-cast
// at the PSP's 480x272 (a pixel is an occluder when its ray hits anything: only sky lies
// behind the sun), the sun projected by the same camera.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Parallel.h"
#include "flarekit/Demo.h"
#include "flarekit/Psp.h"
#include "occlusion/raycast/SceneBvh.h"
#include "scene/CameraMath.h"

namespace flarekit::psp {

Result<PspFrameInput> pspDemoInput(double t) {
    if (!(t >= 0 && t <= 1)) return invalidInput("psp demo: time must be in [0, 1]");
    return pspInputFromScene(demoScene(kScreenWidth, kScreenHeight, t));
}

Result<PspFrameInput> pspInputFromScene(const Scene& scene) {
    if (scene.width != kScreenWidth || scene.height != kScreenHeight)
        return invalidInput("psp: the scene's image must be 480x272 (the PSP screen), got " +
                            std::to_string(scene.width) + "x" + std::to_string(scene.height));
    const SceneBvh bvh(scene);
    const CameraBasis basis = cameraBasis(scene.camera);
    const double tanY = std::tan(scene.camera.fovYDeg * std::numbers::pi / 360.0);
    const double tanX = tanY * kScreenWidth / kScreenHeight;
    PspFrameInput in;
    in.occluders.assign(std::size_t(kScreenWidth * kScreenHeight), 0);
    parallelFor(0, kScreenHeight, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < kScreenWidth; ++x) {
                const double nx = (x + 0.5) / kScreenWidth * 2 - 1,
                             ny = 1 - (y + 0.5) / kScreenHeight * 2;
                const Vec3 d =
                    normalize(basis.forward + basis.right * (nx * tanX) + basis.up * (ny * tanY));
                in.occluders[std::size_t(y * kScreenWidth + x)] =
                    bvh.occluded(scene.camera.position, d) ? 1 : 0;
            }
    });
    Point sun;
    if (projectDirection(scene, scene.sun.direction, sun) && std::isfinite(sun.x) &&
        std::isfinite(sun.y)) {
        in.sunX = int(std::clamp(std::floor(double(sun.x)), -4096.0, 4096.0));
        in.sunY = int(std::clamp(std::floor(double(sun.y)), -4096.0, 4096.0));
    } else {
        in.sunX = in.sunY = -4096;  // behind the camera: off screen, no flare
    }
    return in;
}

}  // namespace flarekit::psp
