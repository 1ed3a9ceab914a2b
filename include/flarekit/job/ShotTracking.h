// SPDX-License-Identifier: Apache-2.0
// --light auto over a sequence: the light finder on each frame and one light followed through
// the shot (flarekit/Shot.h's LightTracker). Like the coverage filter, the tracker at a frame
// runs over a fixed number of the shot's frames before it, starting fresh, so a frame's light is
// the same whichever chunk renders it.
#pragma once

#include <map>
#include <mutex>

#include "flarekit/Flare.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

class ShotTracking {
  public:
    ShotTracking(const ShotPlan& plan, const LightSearchOptions& search,
                 const JobEvents& events = {});
    //! The light at `frame`; `image` is its pixels when the caller has them (else it is read).
    Result<TrackedLight> at(int frame, const Image* image = nullptr);

  private:
    Result<std::vector<LightCandidate>> lightsIn(int frame, const Image* image);

    const ShotPlan& m_plan;
    LightSearchOptions m_search;
    JobEvents m_events;
    //! Frames looked back: half a second of the shot (12 at 24 fps), time for the alpha-beta
    //! filter to settle and for a switch to be decided.
    int m_lookBack;
    std::mutex m_mutex;
    std::map<int, std::vector<LightCandidate>> m_lights;
    std::map<int, TrackedLight> m_tracked;
};

}  // namespace flarekit
