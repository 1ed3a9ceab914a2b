// SPDX-License-Identifier: Apache-2.0
// Sun visibility: the fraction of the sun's disc (uniform over the cone of directions) whose
// rays from the camera hit no object (architecture.md, "Coverage"). `raycast` computes it on
// the CPU and is the ground truth the GPU methods are judged against.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"

namespace flarekit {

//! The texture-mask method's sampling variants (GpuVisibilityOptions::textureMaskVariant in
//! flarekit/gl/GpuVisibility.h), named here so that a front end built without GL takes them.
inline constexpr std::string_view kTextureMaskVariantNames[] = {"square", "circle", "bilinear"};

//! One light's share: for a point light the cone is the one its sphere subtends from the
//! camera (half-angle asin(radius / distance)); a ray keeps the transmittance of the objects
//! it crosses before reaching the light, and coverage is the mean over the cone.
struct LightVisibility {
    double coverage = 0;  //!< 0..1
    double inFrame = 0;   //!< fraction of the cone inside the camera's frame, 0..1
};

struct VisibilityResult {
    std::string method;
    double coverage = 0;  //!< visible fraction of the first light's disc, 0..1
    double inFrame = 0;   //!< fraction of that disc inside the camera's frame, 0..1
    //! Every light of the scene in scene order (sceneLights()); [0] is coverage and inFrame.
    std::vector<LightVisibility> lights;
    std::size_t samples = 0;  //!< rays cast
    double milliseconds = 0;  //!< wall time of the estimate
};

struct RaycastOptions {
    //! Samples per side of the stratified grid: 128^2 = 16384 rays. With one jittered sample
    //! per stratum, a straight edge across the disc gives a standard error of about
    //! sqrt(2 * 128) / 16384 = 0.001, well inside the 0.005 the ground truth is held to.
    int samplesPerSide = 128;
    std::uint64_t seed = 1;  //!< jitter seed: the same seed gives the same estimate
};
inline constexpr Param<RaycastOptions> kRaycastParams[] = {
    param<&RaycastOptions::samplesPerSide>("samples", 1, 4096, "",
                                           "raycast: strata per side (N^2 rays)"),
};

//! The contract's GPU method names (readback pbo query texture-mask texture-mask-screen burnout
//! compute), known to every build; creating one needs the GL library (flarekit/gl/GpuVisibility.h).
const std::vector<std::string>& gpuVisibilityMethods();
bool isGpuVisibilityMethod(const std::string& name);
//! "raycast readback pbo ...": every method name, for error messages.
std::string visibilityMethodList();
//! Ok for raycast or a GPU method; else "method: expected one of raycast ..., got 'NAME'".
Status checkVisibilityMethod(const std::string& name);

Result<VisibilityResult> raycastVisibility(const Scene& scene, const RaycastOptions& options = {});

//! The fraction of the sun's disc (uniform over its cone) inside the camera's frame, from
//! samplesPerSide^2 stratified directions; no occlusion.
double sunInFrameFraction(const Scene& scene, int samplesPerSide = 64);
//! The same for any light of the scene (a point light's cone as in LightVisibility).
double lightInFrameFraction(const Scene& scene, const SceneLight& light, int samplesPerSide = 64);

//! Ray casting for many frames over the same objects (an animation): the BVH is built once
//! from a copy of the scene's objects; each measure() takes the camera, sun and image size of
//! the scene it is given and ignores that scene's objects. Safe to measure from one thread
//! at a time (each call is itself multi-threaded).
class RaycastCaster {
  public:
    explicit RaycastCaster(const Scene& geometry);
    ~RaycastCaster();
    RaycastCaster(RaycastCaster&&) noexcept;
    RaycastCaster& operator=(RaycastCaster&&) noexcept;
    Result<VisibilityResult> measure(const Scene& view, const RaycastOptions& options = {}) const;
    std::size_t primitiveCount() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit
