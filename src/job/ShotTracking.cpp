// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/ShotTracking.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace flarekit {

int trackerLookBack(double fps) {
    return int(std::ceil(0.5 * fps));
}

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
    LightTracker tracker;
    TrackedLight light;
    std::optional<int> previous;
    for (auto it = std::lower_bound(shot.begin(), shot.end(), frame - m_lookBack);
         it != shot.end() && *it <= frame; ++it) {
        auto lights = lightsIn(*it, *it == frame ? image : nullptr);
        if (!lights) return lights.error();
        light = tracker.update(*lights, previous ? double(*it - *previous) : 0.0);
        previous = *it;
    }
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
    while (m_history.front().first < frame - m_lookBack) m_history.pop_front();
    // As ShotTracking::at: a fresh tracker over the frames of the look-back, in order.
    LightTracker tracker;
    TrackedLight light;
    std::optional<int> previous;
    for (const auto& [number, lights] : m_history) {
        light = tracker.update(lights, previous ? double(number - *previous) : 0.0);
        previous = number;
    }
    return light;
}

}  // namespace flarekit
