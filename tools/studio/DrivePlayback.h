// SPDX-License-Identifier: Apache-2.0
// The demo drive played in the studio: a worker thread with a headless GL context of its own
// renders the frames in order through the frame pipeline (the temporal filter carries its state
// from frame to frame, so each frame is made once, in order, and kept), and the window shows
// whichever frame the timeline is on, with the sun's raw and filtered coverage per frame. The
// frames are exactly `flarekit demo`'s at the same settings (tested against its PNGs and its
// coverage.csv). Each frame keeps the method's working textures for the diagnostic strip.
#pragma once

#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "Diagnostics.h"
#include "flarekit/Demo.h"
#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"

namespace flarekit::studio {

struct DriveFrame {
    Image8 image;  //!< the frame as `flarekit demo` writes it: 8-bit sRGB RGBA
    double time = 0, rawCoverage = 0, filteredCoverage = 0, inFrame = 0;
    Point sun;
    bool sunInFront = false;
    //! The GPU method's working textures for this frame (Diagnostics.h; none for raycast and
    //! the late methods).
    std::vector<DiagnosticPicture> methodViews;
};

class DrivePlayback {
  public:
    //! Checks the settings and the memory the kept frames need (8-bit RGBA each), then starts
    //! the worker; its errors (no GL, a bad preset) come back through error().
    static Result<std::unique_ptr<DrivePlayback>> start(const DemoSettings& settings,
                                                        const Preset& preset);
    ~DrivePlayback();  //!< stops the worker between two frames
    DrivePlayback(const DrivePlayback&) = delete;
    DrivePlayback& operator=(const DrivePlayback&) = delete;

    const DemoSettings& settings() const { return m_settings; }
    int frameCount() const { return m_settings.frames; }
    int ready() const { return m_ready.load(); }  //!< frames made so far, in order
    bool finished() const { return m_finished.load(); }
    std::string error() const;  //!< empty unless the worker stopped on one
    //! A copy of frame `i` (< ready()).
    DriveFrame frame(int i) const;
    //! The raw and filtered coverage of the frames made so far.
    void coverage(std::vector<float>& raw, std::vector<float>& filtered) const;
    //! frame,time_s,coverage_raw,coverage_smoothed,in_frame: the columns of `flarekit demo`'s
    //! coverage.csv that the studio shows.
    std::string coverageCsv() const;

  private:
    DrivePlayback(const DemoSettings& settings, const Preset& preset);
    void work();

    DemoSettings m_settings;
    Preset m_preset;
    mutable std::mutex m_mutex;
    std::vector<DriveFrame> m_frames;  //!< guarded by m_mutex
    std::string m_error;               //!< guarded by m_mutex
    std::atomic<int> m_ready{0};
    std::atomic<bool> m_finished{false}, m_stop{false};
    std::thread m_thread;  //!< started last, once every member it reads is set
};

}  // namespace flarekit::studio
