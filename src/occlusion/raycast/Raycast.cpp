// `raycast`: the ground-truth coverage. Directions are spread uniformly over the sun's cone
// (uniform in solid angle) by stratified jittered samples: a square grid of strata is mapped
// to the unit disc by Shirley and Chiu's concentric map (equal-area, so the strata stay equal
// and compact), and the disc to the cone by 1 - cos(theta) = rho^2 (1 - cos(alpha)), which is
// equal-area on the sphere too. Rows of strata are cast in parallel.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>

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

}  // namespace

double sunInFrameFraction(const Scene& scene, int samplesPerSide) {
    const Frame frame = cameraFrame(scene);
    const occlusion::SunCone cone(scene.sun);
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
    const occlusion::SunCone cone(scene.sun);
    const int n = options.samplesPerSide;

    std::atomic<std::size_t> visible{0}, framed{0};
    parallelFor(0, n, 4, [&](int row0, int row1) {
        std::size_t vis = 0, fr = 0;
        for (int row = row0; row < row1; ++row) {
            SplitMix64 rng(options.seed * 0x9E3779B97F4A7C15ull +
                           std::uint64_t(row));  // per row: thread-count independent
            for (int col = 0; col < n; ++col) {
                const double a = 2.0 * (double(col) + rng.nextFloat()) / n - 1.0,
                             b = 2.0 * (double(row) + rng.nextFloat()) / n - 1.0;
                const Vec3 d = cone.fromSquare(a, b);
                vis += bvh.occluded(scene.camera.position, d) ? 0 : 1;
                fr += inFrame(frame, d) ? 1 : 0;
            }
        }
        visible += vis;
        framed += fr;
    });
    VisibilityResult r;
    r.method = "raycast";
    r.samples = std::size_t(n) * std::size_t(n);
    r.coverage = double(visible) / double(r.samples);
    r.inFrame = double(framed) / double(r.samples);
    r.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace flarekit
