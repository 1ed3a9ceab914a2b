// SPDX-License-Identifier: Apache-2.0
// Encoding numbered PNG frames into an MP4 with ffmpeg, when ffmpeg is installed: a program run,
// not a library linked (NOTICE). Any front end that writes a shot or the demo uses it.
#pragma once

#include <string>

#include "flarekit/Result.h"

namespace flarekit {

//! The ffmpeg on PATH, or "" when there is none.
std::string findFfmpeg();

//! Runs ffmpeg on `pattern` (e.g. DIR/frame_%04d.png) at `fps` into `output` (H.264 yuv420p,
//! or MPEG-4 part 2 when this ffmpeg has no libx264), through a temporary file renamed at the
//! end. ffmpeg's messages go to `logPath`.
Status encodeVideo(const std::string& ffmpeg, const std::string& pattern, double fps,
                   const std::string& output, const std::string& logPath);

}  // namespace flarekit
