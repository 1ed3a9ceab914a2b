// SPDX-License-Identifier: Apache-2.0
// Following one light through a shot (see flarekit/Shot.h): gate, alpha-beta filter, and a
// switch only after a brighter light has stood elsewhere for several frames.
#include <algorithm>
#include <cmath>

#include "flarekit/Shot.h"

namespace flarekit {

namespace {
//! A candidate that is not accepted stands for the followed light only with at least this share
//! of the peak the light last had: a sun dimmed by haze or outshone elsewhere keeps most of its
//! peak, while the glow left around a sun hidden behind a building peaks thousands of times
//! lower (6,000x in blender-data's city HDRI) and would drag the track across the sky.
constexpr double kHeldPeakShare = 0.1;

double distance(Point a, Point b) {
    return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}
}  // namespace

TrackedLight LightTracker::update(const std::vector<LightCandidate>& lights, double dt) {
    // Only accepted lights start or take over the track; the followed one is matched among every
    // candidate, so a sun outshone in one frame (and so not accepted there) is still followed.
    const LightCandidate* brightest = nullptr;
    for (const LightCandidate& l : lights)
        if (l.accepted && (!brightest || l.flux > brightest->flux)) brightest = &l;
    auto start = [&](const LightCandidate& l) {
        m_started = true;
        m_position = l.position;
        m_velocity = {0, 0};
        m_radius = l.radius;
        m_challenged = 0;
        m_measured = 1;
        m_peak = l.peak;
        return TrackedLight{true, l.position, l.flux, l.flareScale};
    };
    if (!m_started) return brightest ? start(*brightest) : TrackedLight{};
    const Point predicted{float(m_position.x + m_velocity.x * dt),
                          float(m_position.y + m_velocity.y * dt)};
    const double gate = std::max(m_params.minGatePixels, m_params.gate * (double(m_radius) + 4.0));
    // The followed light: the accepted light nearest the prediction inside the gate. In a frame
    // where it is not accepted (outshone by a glint elsewhere), the candidate with the highest
    // peak there: the light's core, never the wide dim glow around it (a sky's halo carries more
    // flux than the sun itself in the city HDRI, at a peak 6,000 times lower). With no candidate
    // near the light's own peak (kHeldPeakShare) the light is hidden: the track holds its
    // prediction.
    const LightCandidate* followed = nullptr;
    for (const LightCandidate& l : lights) {
        const double d = distance(l.position, predicted);
        if (l.accepted && d <= gate && (!followed || d < distance(followed->position, predicted)))
            followed = &l;
    }
    if (!followed)
        for (const LightCandidate& l : lights)
            if (distance(l.position, predicted) <= gate && l.peak >= kHeldPeakShare * m_peak &&
                (!followed || l.peak > followed->peak))
                followed = &l;
    // A brighter light elsewhere takes over only once it has stayed brighter (and in one place)
    // for switchFrames frames in a row; the followed light lost counts as outshone.
    const double reference = followed ? followed->flux : 0.0;
    const LightCandidate* challenger =
        brightest && brightest != followed && brightest->flux > m_params.switchRatio * reference
            ? brightest
            : nullptr;
    if (challenger) {
        const bool same = m_challenged > 0 && distance(challenger->position, m_challenger) <=
                                                  m_params.gate * (challenger->radius + 4.0);
        m_challenged = same ? m_challenged + 1 : 1;
        m_challenger = challenger->position;
        if (m_challenged >= m_params.switchFrames) return start(*challenger);
    } else {
        m_challenged = 0;
    }
    if (!followed) {
        // Not seen this frame: coast on the prediction, no flare.
        m_position = predicted;
        return TrackedLight{false, predicted, 0, 0};
    }
    const double rx = followed->position.x - predicted.x, ry = followed->position.y - predicted.y;
    if (m_measured == 1 && dt > 0) {
        // The second sighting: the velocity from the two, the position as measured (the
        // filter's usual start, so a light moving steadily is followed without lag).
        m_velocity = {float(rx / dt), float(ry / dt)};
        m_position = followed->position;
    } else {
        m_position = {float(predicted.x + m_params.alpha * rx),
                      float(predicted.y + m_params.alpha * ry)};
        if (dt > 0)
            m_velocity = {float(m_velocity.x + m_params.beta * rx / dt),
                          float(m_velocity.y + m_params.beta * ry / dt)};
    }
    ++m_measured;
    m_radius = followed->radius;
    m_peak = followed->peak;
    return TrackedLight{true, m_position, followed->flux, followed->flareScale};
}

}  // namespace flarekit
