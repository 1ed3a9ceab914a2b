// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/ShotTracking.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace flarekit {

int trackerLookBack(double fps) {
    return int(std::ceil(0.5 * fps));
}

namespace {

//! A fresh tracker over the frames of a look-back, in order: the light at the last of them.
//! ShotTracking and LiveTracking both end here, so the two give the same light.
TrackedLight trackLookBack(const std::vector<FrameLights>& frames) {
    LightTracker tracker;
    TrackedLight light;
    std::optional<int> previous;
    for (const auto& [frame, lights] : frames) {
        light = tracker.update(lights, previous ? double(frame - *previous) : 0.0);
        previous = frame;
    }
    return light;
}

}  // namespace

ShotTracking::ShotTracking(const ShotPlan& plan, const LightSearchOptions& search,
                           const JobEvents& events)
    : m_plan(plan), m_search(search), m_events(events), m_lookBack(trackerLookBack(plan.fps)) {}

Result<std::vector<LightCandidate>> ShotTracking::lightsIn(int frame, const Image* image) {
    {
        std::lock_guard lock(m_mutex);
        if (auto it = m_lights.find(frame); it != m_lights.end()) return it->second;
    }
    std::optional<LoadedImage> loaded;
    if (!image) {
        auto read = readJobInput(m_plan.in.path(frame), {}, m_events);
        if (!read) return read.error();
        loaded = std::move(*read);
        image = &loaded->image;
    }
    std::vector<LightCandidate> lights = findLights(*image, m_search).candidates;
    std::lock_guard lock(m_mutex);
    m_lights[frame] = lights;
    return lights;
}

Result<TrackedLight> ShotTracking::at(int frame, const Image* image) {
    {
        std::lock_guard lock(m_mutex);
        if (auto it = m_tracked.find(frame); it != m_tracked.end()) return it->second;
    }
    const auto& shot = m_plan.shotFrames;
    std::vector<FrameLights> window;
    for (auto it = std::lower_bound(shot.begin(), shot.end(), frame - m_lookBack);
         it != shot.end() && *it <= frame; ++it) {
        auto lights = lightsIn(*it, *it == frame ? image : nullptr);
        if (!lights) return lights.error();
        window.emplace_back(*it, std::move(*lights));
    }
    const TrackedLight light = trackLookBack(window);
    std::lock_guard lock(m_mutex);
    m_tracked[frame] = light;
    return light;
}

LiveTracking::LiveTracking(const LightSearchOptions& search, double fps)
    : m_search(search), m_lookBack(trackerLookBack(fps)) {}

TrackedLight LiveTracking::next(int frame, const Image& image) {
    if (!m_history.empty() &&
        (frame <= m_history.back().first || frame - m_history.back().first > m_lookBack))
        m_history.clear();
    m_history.emplace_back(frame, findLights(image, m_search).candidates);
    const auto first = std::find_if(m_history.begin(), m_history.end(), [&](const FrameLights& f) {
        return f.first >= frame - m_lookBack;
    });
    m_history.erase(m_history.begin(), first);
    return trackLookBack(m_history);
}

}  // namespace flarekit
