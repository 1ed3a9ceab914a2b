// SPDX-License-Identifier: Apache-2.0
#include "job/ShotLight.h"

#include <cstdio>
#include <vector>

namespace flarekit {

namespace {
//! The frames of the plan outside a file's keys, named in one warning.
void warnHeld(const JobEvents& events, const std::string& file, const std::vector<int>& held,
              double first, double last) {
    if (held.empty()) return;
    char range[80];
    std::snprintf(range, sizeof range, " are outside the keys (%g to %g): ", first, last);
    events.warn(file + ": frames " + describeFrames(held) + range + "the end keys are held");
}
}  // namespace

Result<std::unique_ptr<ShotLight>> ShotLight::load(const ApplyOptions& a, const ShotPlan& plan,
                                                   const JobEvents& events) {
    std::unique_ptr<ShotLight> light(new ShotLight(plan));
    light->m_fixed = a.light;
    light->m_measured = a.fluxMode == FluxMode::Measured;
    light->m_search = a.lightSearch;
    light->m_guardBand = a.occlusion.temporal.guardBand;
    if (!a.lightTrack.empty()) {
        auto loaded = loadLightTrack(a.lightTrack);
        if (!loaded) return loaded.error();
        light->m_track = std::move(*loaded);
        std::vector<int> held;
        for (int f : plan.frames)
            if (light->m_track->at(f).held) held.push_back(f);
        warnHeld(events, a.lightTrack, held, light->m_track->keys.front().frame,
                 light->m_track->keys.back().frame);
    } else if (!a.camera.empty()) {
        auto loaded = loadCameraTrack(a.camera);
        if (!loaded) return loaded.error();
        light->m_camera = std::move(*loaded);
        light->m_sun = a.sunDir.has_value();
        light->m_world = a.sunDir ? normalize(*a.sunDir) : *a.lightWorld;
        std::vector<int> held;
        for (int f : plan.frames) {
            bool h = false;
            light->m_camera->at(f, &h);
            if (h) held.push_back(f);
        }
        warnHeld(events, a.camera, held, light->m_camera->keys.front().frame,
                 light->m_camera->keys.back().frame);
    } else if (!a.light) {
        light->m_tracking.emplace(plan, a.lightSearch, events);
    }
    return light;
}

Point ShotLight::position(int frame, const Image* image) {
    if (m_fixed) return *m_fixed;
    if (m_track) return m_track->at(frame).position;
    if (m_camera) {
        Point p;
        projectLight(m_camera->at(frame), m_plan.width, m_plan.height, m_world, m_sun, p);
        return p;
    }
    auto t = m_tracking->at(frame, image);
    return t ? t->position : Point{};
}

Result<ShotLight::Weight> ShotLight::weight(int frame, const Image& image) {
    if (m_track) {
        const LightTrack::Sample s = m_track->at(frame);
        const bool measure = m_measured && !m_track->hasIntensity;
        return Weight{
            measure ? measureLightAt(image, s.position, m_search).flareScale : s.intensity, true};
    }
    if (m_fixed && m_measured) return Weight{measureLightAt(image, *m_fixed, m_search).flareScale};
    if (m_camera) {
        Point p;
        if (!projectLight(m_camera->at(frame), m_plan.width, m_plan.height, m_world, m_sun, p))
            return Weight{0, false};
        return Weight{float(edgeFade(p, m_plan.width, m_plan.height, m_guardBand)), true};
    }
    if (m_tracking) {
        auto t = m_tracking->at(frame, &image);
        if (!t) return t.error();
        return Weight{t->found ? t->flareScale : 0.f, t->found};
    }
    return Weight{};
}

}  // namespace flarekit
