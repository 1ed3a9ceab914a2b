// SPDX-License-Identifier: Apache-2.0
// What a flare does over time, the way players expect from games: coverage smoothed with
// separate attack (sun appearing) and release (sun disappearing) times so sample noise does not
// flicker, a fade as the sun nears the frame edge, and exposure that dims while the camera
// stares at the visible sun (GPG2 texture-masking article: "use the intensity for
// exposure/pupil adaptation"). Every step is frame-rate independent: a time constant tau
// moves a value by 1 - exp(-dt / tau) of the way to its target per frame.
#pragma once

#include "flarekit/Flare.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"

namespace flarekit {

//! Attack 0.04 s: about one frame at 30 fps, so a sun stepping out from behind a tree lights up
//! at once. Release 0.12 s: three frames, long enough to swallow a single frame of raycast or
//! 8-bit mask noise, short enough that the flare still dies with the sun behind a pole.
//! Guard band 0.08 of the shorter side: the flare is full strength 58 px inside a 720p frame's
//! edge and gone at the edge, where on-screen methods lose the disc anyway.
//! Adaptation strength 0.6: staring at the fully visible sun dims exposure to 1 / 1.6.
//! The eye closes down faster than it opens up (roughly 0.3 s vs 1.5 s for a pupil).
struct TemporalParams {
    double attackSeconds = 0.04;
    double releaseSeconds = 0.12;
    double guardBand = 0.08;
    double adaptStrength = 0.6;
    double adaptDarkenSeconds = 0.3;
    double adaptBrightenSeconds = 1.5;
};

//! The keys are also the CLI flags (--attack, --guard-band, ...).
inline constexpr Param<TemporalParams> kTemporalParams[] = {
    param<&TemporalParams::attackSeconds>("attack", 0, 10, "s",
                                          "coverage rise time constant (sun appearing)"),
    param<&TemporalParams::releaseSeconds>("release", 0, 10, "s",
                                           "coverage fall time constant (sun hidden)"),
    param<&TemporalParams::guardBand>("guard-band", 0, 0.5, "shorter side", "edge fade width"),
    param<&TemporalParams::adaptStrength>(
        "adapt-strength", 0, 10, "", "exposure dimming when staring at the visible sun (0 = off)"),
    param<&TemporalParams::adaptDarkenSeconds>("adapt-darken", 0, 30, "s",
                                               "exposure darkening time constant"),
    param<&TemporalParams::adaptBrightenSeconds>("adapt-brighten", 0, 30, "s",
                                                 "exposure recovery time constant"),
};

//! Range check of every field; the error names the field ("guard-band: expected ...").
Status validateTemporalParams(const TemporalParams& params);

//! The fraction 1 - exp(-dt / tau) of the way a value moves in dt seconds (1 when tau is 0).
double smoothingStep(double dtSeconds, double tauSeconds);

//! Edge fade of a light at `pixel` in a width x height frame: 1 at least guardBand x the
//! shorter side inside every edge, 0 on or outside the edge, smoothstep between.
double edgeFade(Point pixel, int width, int height, double guardBand);

struct TemporalState {
    double coverage = 0;     //!< smoothed coverage, 0..1
    double edgeFade = 0;     //!< this frame's edge fade, 0..1
    double exposure = 1;     //!< adapted exposure multiplier
    double flareWeight = 0;  //!< coverage x edgeFade: what the flare's intensity is scaled by
};

class TemporalFilter {
  public:
    explicit TemporalFilter(const TemporalParams& params = {}) : m_params(params) {}
    //! One frame: the measured coverage, where the sun projects (and whether it is in front),
    //! the frame size and the time since the previous frame. The first update starts from
    //! its own values instead of fading in from zero.
    TemporalState update(double rawCoverage, Point sunPixel, bool sunInFront, int width, int height,
                         double dtSeconds);
    const TemporalState& state() const { return m_state; }

  private:
    TemporalParams m_params;
    TemporalState m_state;
    bool m_started = false;
};

}  // namespace flarekit
