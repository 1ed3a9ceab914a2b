// SPDX-License-Identifier: Apache-2.0
// --light auto over a sequence: the light finder on each frame and one light followed through
// the shot (flarekit/Shot.h's LightTracker). Like the coverage filter, the tracker at a frame
// runs over a fixed number of the shot's frames before it, starting fresh, so a frame's light is
// the same whichever chunk renders it.
#pragma once

#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

//! A frame's number and the light finder's candidates in it.
using FrameLights = std::pair<int, std::vector<LightCandidate>>;

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
    int m_lookBack;  //!< trackerLookBack(fps)
    std::mutex m_mutex;
    std::map<int, std::vector<LightCandidate>> m_lights;
    std::map<int, TrackedLight> m_tracked;
};

//! The look-back of the tracker at `fps` frames per second: half a second of the shot (12 at
//! 24 fps), time for the alpha-beta filter to settle and for a switch to be decided.
int trackerLookBack(double fps);

//! The same light for frames a host hands over one at a time (a video editor's filter, which
//! never sees the whole shot): each frame's light is what ShotTracking gives the frame of the
//! same number in a file sequence, because both run a fresh tracker over the same look-back.
class LiveTracking {
  public:
    explicit LiveTracking(const LightSearchOptions& search, double fps = 24);
    //! The light in `image`, frame number `frame`. A frame at or before the previous one, or
    //! more than the look-back after it (a host seeking), forgets what came before.
    TrackedLight next(int frame, const Image& image);

  private:
    LightSearchOptions m_search;
    int m_lookBack;
    std::vector<FrameLights> m_history;  //!< the look-back's frames, oldest first
};

}  // namespace flarekit
