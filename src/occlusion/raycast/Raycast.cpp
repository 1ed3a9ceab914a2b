// SPDX-License-Identifier: Apache-2.0
// `raycast`: the ground-truth coverage. Directions are spread uniformly over the sun's cone
// (uniform in solid angle) by stratified jittered samples: a square grid of strata is mapped
// to the unit disc by Shirley and Chiu's concentric map (equal-area, so the strata stay equal
// and compact), and the disc to the cone by 1 - cos(theta) = rho^2 (1 - cos(alpha)), which is
// equal-area on the sphere too. Rows of strata are cast in parallel.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/Parallel.h"
#include "core/Random.h"
#include "flarekit/Visibility.h"
#include "occlusion/SunCone.h"
#include "occlusion/raycast/SceneBvh.h"
#include "scene/CameraMath.h"

namespace flarekit {

namespace {

constexpr double kPi = std::numbers::pi;

struct Frame {  // camera basis and frustum half-extents, for the in-frame fraction
    CameraBasis basis;
    double tanHalfY, tanHalfX;
};

Frame cameraFrame(const Scene& s) {
    Frame f;
    f.basis = cameraBasis(s.camera);
    f.tanHalfY = std::tan(s.camera.fovYDeg * kPi / 360.0);
    f.tanHalfX = f.tanHalfY * double(s.width) / double(s.height);
    return f;
}

bool inFrame(const Frame& f, Vec3 d) {
    const double z = dot(d, f.basis.forward);
    if (z <= 0) return false;
    return std::abs(dot(d, f.basis.right)) <= f.tanHalfX * z &&
           std::abs(dot(d, f.basis.up)) <= f.tanHalfY * z;
}

//! A light as seen from the camera: its cone of directions and how far each ray goes before
//! it reaches the light (infinity for a directional light, the near side of a point light's
//! sphere). A camera inside a sphere light sees it in every direction at no distance.
struct LightCone {
    LightCone(const Scene& scene, const SceneLight& light)
        : cone(light.direction, light.angularRadiusDeg * kPi / 180.0) {
        if (light.type != LightType::Point) return;
        point = true;
        centre = light.position;
        radius = light.radius;
        const Vec3 toLight = centre - scene.camera.position;
        const double distance = length(toLight);
        inside = distance <= radius;
        cone = occlusion::SunCone(inside ? scene.camera.lookAt - scene.camera.position : toLight,
                                  inside ? kPi : std::asin(radius / distance));
    }
    double reach(Vec3 origin, Vec3 d) const {  // d is unit length
        if (!point) return std::numeric_limits<double>::infinity();
        if (inside) return 0;
        const Vec3 oc = centre - origin;
        const double b = dot(oc, d), c = dot(oc, oc) - radius * radius;
        return b - std::sqrt(std::max(0.0, b * b - c));  // rim rays graze: the root is 0
    }
    occlusion::SunCone cone;
    bool point = false, inside = false;
    Vec3 centre;
    double radius = 0;
};

double inFrameFraction(const Frame& frame, const occlusion::SunCone& cone, int samplesPerSide) {
    const int n = std::max(1, samplesPerSide);
    std::size_t framed = 0;
    for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
            framed += inFrame(frame, cone.fromSquare(2.0 * (col + 0.5) / n - 1.0,
                                                     2.0 * (row + 0.5) / n - 1.0))
                          ? 1
                          : 0;
        }
    }
    return double(framed) / double(std::size_t(n) * std::size_t(n));
}

}  // namespace

double sunInFrameFraction(const Scene& scene, int samplesPerSide) {
    return inFrameFraction(cameraFrame(scene), occlusion::SunCone(scene.sun), samplesPerSide);
}

double lightInFrameFraction(const Scene& scene, const SceneLight& light, int samplesPerSide) {
    return inFrameFraction(cameraFrame(scene), LightCone(scene, light).cone, samplesPerSide);
}

struct RaycastCaster::Impl {
    explicit Impl(const Scene& geometry) : scene(geometry), bvh(scene) {}
    Scene scene;  // the BVH refers to its objects
    SceneBvh bvh;
};

RaycastCaster::RaycastCaster(const Scene& geometry) : m(std::make_unique<Impl>(geometry)) {}
RaycastCaster::~RaycastCaster() = default;
RaycastCaster::RaycastCaster(RaycastCaster&&) noexcept = default;
RaycastCaster& RaycastCaster::operator=(RaycastCaster&&) noexcept = default;
std::size_t RaycastCaster::primitiveCount() const {
    return m->bvh.primitiveCount();
}

Result<VisibilityResult> raycastVisibility(const Scene& scene, const RaycastOptions& options) {
    if (Status s = validateScene(scene); !s) return invalidInput("scene: " + s.error().message);
    const auto start = std::chrono::steady_clock::now();
    auto result = RaycastCaster(scene).measure(scene, options);
    if (result) {  // include the BVH build, as before
        result->milliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    return result;
}

Result<VisibilityResult> RaycastCaster::measure(const Scene& scene,
                                                const RaycastOptions& options) const {
    if (options.samplesPerSide < 1 || options.samplesPerSide > 4096) {
        return invalidInput("raycast samples per side: expected an integer in [1, 4096], got " +
                            std::to_string(options.samplesPerSide));
    }
    const auto start = std::chrono::steady_clock::now();
    const SceneBvh& bvh = m->bvh;
    const Frame frame = cameraFrame(scene);
    const int n = options.samplesPerSide;
    const Vec3 eye = scene.camera.position;

    VisibilityResult r;
    r.method = "raycast";
    const std::size_t rays = std::size_t(n) * std::size_t(n);
    for (const SceneLight& light : sceneLights(scene)) {
        const LightCone lightCone(scene, light);
        // Per-row sums added in row order: the estimate does not depend on the thread count.
        std::vector<double> rowVisible(std::size_t(n), 0.0);
        std::vector<std::size_t> rowFramed(std::size_t(n), 0);
        parallelFor(0, n, 4, [&](int row0, int row1) {
            for (int row = row0; row < row1; ++row) {
                double vis = 0;
                std::size_t fr = 0;
                SplitMix64 rng(options.seed * 0x9E3779B97F4A7C15ull +
                               std::uint64_t(row));  // per row: thread-count independent
                for (int col = 0; col < n; ++col) {
                    const double a = 2.0 * (double(col) + rng.nextFloat()) / n - 1.0,
                                 b = 2.0 * (double(row) + rng.nextFloat()) / n - 1.0;
                    const Vec3 d = lightCone.cone.fromSquare(a, b);
                    vis += bvh.transmittance(eye, d, lightCone.reach(eye, d));
                    fr += inFrame(frame, d) ? 1 : 0;
                }
                rowVisible[std::size_t(row)] = vis;
                rowFramed[std::size_t(row)] = fr;
            }
        });
        double visible = 0;
        std::size_t framed = 0;
        for (int row = 0; row < n; ++row) {
            visible += rowVisible[std::size_t(row)];
            framed += rowFramed[std::size_t(row)];
        }
        r.lights.push_back({visible / double(rays), double(framed) / double(rays)});
        r.samples += rays;
    }
    r.coverage = r.lights.front().coverage;
    r.inFrame = r.lights.front().inFrame;
    r.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace flarekit
