// SPDX-License-Identifier: Apache-2.0
// The demo job (`flarekit demo`): the built-in drive rendered to numbered PNG frames, a coverage
// log and a strip of six frames, in a headless context. Frames are encoded on a writer thread
// so the next frame's GL, raycast and flare work overlaps them; encodeDemoVideo makes the MP4.
#pragma once

#include <string>

#include "flarekit/Demo.h"
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"
#include "flarekit/job/Job.h"

namespace flarekit::gl {

struct DemoJobOptions {
    std::string outDir;  //!< made when missing
    DemoSettings settings;
    std::string preset = kDefaultSpritePreset;
    //! Render and time the drive but write nothing (the render stage without the writer).
    bool noFrames = false;
    //! Count an MP4 the front end will make from the frames (a tenth of their size) in the disk
    //! check.
    bool reserveVideo = true;
    EncodeSettings encode;
};

struct DemoReport {
    int frames = 0, digits = 4;                          //!< frame_0001.png ..: the number's width
    double renderMs = 0, visibilityMs = 0, flareMs = 0;  //!< per frame, averaged
    std::string renderer, platform;                      //!< the GL the frames were drawn on
    //! The frame's file (0-based index): OUT/frame_0001.png, ...
    std::string framePath(const DemoJobOptions& options, int index) const;
};

//! Checked before the first frame: the settings, the preset's work, the GL limits of the frame
//! size and the disk the frames need. Progress per frame and cancellation through `events`; a
//! cancel leaves the complete frames, in order, and nothing else.
Result<DemoReport> runDemoJob(const DemoJobOptions& options, const JobEvents& events = {});

//! The frames as OUT/demo.mp4 (encodeVideo at the drive's frame rate); ffmpeg's log is kept as
//! OUT/ffmpeg.log only when it fails. False, and nothing written, when ffmpeg is not installed.
Result<bool> encodeDemoVideo(const DemoJobOptions& options, const DemoReport& report);

}  // namespace flarekit::gl
