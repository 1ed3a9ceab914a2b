// SPDX-License-Identifier: Apache-2.0
// Where a shot's light is per frame and how strong, from whichever source an apply job was
// given: a fixed point, a track, a camera with a light in the world (or the sun's direction), or
// the light the finder follows through the shot.
#pragma once

#include <memory>
#include <optional>

#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/ShotTracking.h"

namespace flarekit {

class ShotLight {
  public:
    //! The sources of `options` loaded and checked before any frame; a warning names the frames
    //! outside a track's or camera's keys (the end keys are held there).
    static Result<std::unique_ptr<ShotLight>> load(const ApplyOptions& options,
                                                   const ShotPlan& plan, const JobEvents& events);

    //! The light's position in `frame`; `image` is its pixels when the caller has them.
    Point position(int frame, const Image* image = nullptr);
    //! The intensity multiplier: the track's, the edge fade of a projected light, the followed
    //! light's flare scale, a placed light's measured flare scale (FluxMode::Measured). `present`
    //! false: no light this frame (behind the camera, or the followed light not seen).
    struct Weight {
        float weight = 1;
        bool present = true;
    };
    Result<Weight> weight(int frame, const Image& image);
    //! True when the light is the one the finder follows (no position was given).
    bool followsFinder() const { return m_tracking.has_value(); }

  private:
    explicit ShotLight(const ShotPlan& plan) : m_plan(plan) {}

    const ShotPlan& m_plan;
    std::optional<Point> m_fixed;
    bool m_measured = true;  //!< a placed light's flux measured in each frame (FluxMode)
    LightSearchOptions m_search;
    std::optional<LightTrack> m_track;
    std::optional<CameraTrack> m_camera;
    Vec3 m_world;
    bool m_sun = false;
    double m_guardBand = 0.08;
    std::optional<ShotTracking> m_tracking;
};

}  // namespace flarekit
