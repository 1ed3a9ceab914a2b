// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <cmath>

#include "core/Smoothstep.h"
#include "flarekit/ParamText.h"
#include "flarekit/Temporal.h"

namespace flarekit {

Status validateTemporalParams(const TemporalParams& p) {
    return validateParams<TemporalParams>(p, kTemporalParams, "");
}

double smoothingStep(double dtSeconds, double tauSeconds) {
    if (tauSeconds <= 0) return 1.0;
    return 1.0 - std::exp(-std::max(0.0, dtSeconds) / tauSeconds);
}

double edgeFade(Point pixel, int width, int height, double guardBand) {
    const double inside = std::min(
        {double(pixel.x), width - double(pixel.x), double(pixel.y), height - double(pixel.y)});
    if (inside <= 0) return 0;
    const double band = guardBand * std::min(width, height);
    if (band <= 0) return 1;
    return smoothstep01(inside / band);
}

TemporalState TemporalFilter::update(double rawCoverage, Point sunPixel, bool sunInFront, int width,
                                     int height, double dtSeconds) {
    const double target = std::isfinite(rawCoverage) ? std::clamp(rawCoverage, 0.0, 1.0) : 0.0;
    TemporalState& s = m_state;
    s.edgeFade = sunInFront ? edgeFade(sunPixel, width, height, m_params.guardBand) : 0.0;
    if (!m_started) {
        s.coverage = target;
    } else {
        const double tau = target > s.coverage ? m_params.attackSeconds : m_params.releaseSeconds;
        s.coverage += smoothingStep(dtSeconds, tau) * (target - s.coverage);
    }
    s.flareWeight = s.coverage * s.edgeFade;
    // Staring: how much visible sun the camera looks at, full weight at the frame centre and
    // half at the corners (a sun in the corner of the eye dazzles less).
    const double dx = sunPixel.x - 0.5 * width, dy = sunPixel.y - 0.5 * height;
    const double offCentre =
        std::sqrt(dx * dx + dy * dy) / (0.5 * std::hypot(double(width), double(height)));
    const double staring = s.flareWeight * (1.0 - 0.5 * smoothstep01(offCentre));
    const double targetExposure = 1.0 / (1.0 + m_params.adaptStrength * staring);
    if (!m_started) {
        s.exposure = targetExposure;
    } else {
        // Adapt in log space: equal ratios take equal time, as the eye does.
        const double tau = targetExposure < s.exposure ? m_params.adaptDarkenSeconds
                                                       : m_params.adaptBrightenSeconds;
        s.exposure =
            std::exp(std::log(s.exposure) + smoothingStep(dtSeconds, tau) *
                                                (std::log(targetExposure) - std::log(s.exposure)));
    }
    m_started = true;
    return s;
}

}  // namespace flarekit
