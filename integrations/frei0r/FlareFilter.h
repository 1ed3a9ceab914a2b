// SPDX-License-Identifier: Apache-2.0
// One instance of the frei0r filter: a host's RGBA8888 frames (sRGB colour, straight alpha)
// flared through the library's pixel jobs, the same work `flarekit apply`, `postfx` and
// `lens render` do on a PNG frame. No frei0r type appears here; Frei0rPlugin.cpp adapts it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "FilterSettings.h"
#include "HostFlare.h"
#include "flarekit/job/ShotTracking.h"

namespace flarekit::frei0r {

class FlareFilter {
  public:
    FlareFilter(int width, int height) : m_width(width), m_height(height) {}

    const FilterSettings& settings() const { return m_settings; }
    //! New settings: a new mode or preset is loaded at the next frame, and a new light source,
    //! threshold or frame rate starts the track again; the rest (x, y, intensity, which a host
    //! may keyframe) only changes the next frame.
    void set(const FilterSettings& next);

    //! One frame at `time` (the host's clock, any unit; frames arrive in order): `in` flared
    //! into `out` (both width x height RGBA8888). Never throws: on a failure the frame is copied
    //! unchanged and one line goes to stderr (once per distinct message).
    void update(double time, const std::uint32_t* in, std::uint32_t* out) noexcept;

  private:
    Status render(double time, const std::uint8_t* in, std::uint8_t* out);
    //! The frame's number in the clip: frames counted by the smallest step between times seen.
    int frameAt(double time);
    void report(const std::string& line);

    int m_width, m_height;
    FilterSettings m_settings;
    std::optional<host::Look> m_look;  //!< loaded at the first frame after a change
    std::optional<LiveTracking> m_tracking;
    std::optional<double> m_lastTime;
    double m_step = 0;
    int m_frame = 0;
    TrackedLight m_lastLight;
    std::string m_lastReport;
};

}  // namespace flarekit::frei0r
