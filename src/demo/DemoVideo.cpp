// SPDX-License-Identifier: Apache-2.0
// The demo's MP4: its PNG frames through ffmpeg, when ffmpeg is installed.
#include <cstdio>
#include <filesystem>

#include "flarekit/Video.h"
#include "flarekit/gl/DemoJob.h"

namespace flarekit::gl {

Result<bool> encodeDemoVideo(const DemoJobOptions& o, const DemoReport& r) {
    const std::string ffmpeg = findFfmpeg();
    if (ffmpeg.empty()) return false;
    const std::string dir = std::filesystem::path(o.outDir).string() + "/";
    char pattern[64];
    std::snprintf(pattern, sizeof pattern, "frame_%%0%dd.png", r.digits);
    if (Status s = encodeVideo(ffmpeg, dir + pattern, o.settings.fps, dir + "demo.mp4",
                               dir + "ffmpeg.log");
        !s)
        return s.error();
    std::error_code ec;
    std::filesystem::remove(dir + "ffmpeg.log", ec);  // empty on success; kept only on failure
    return true;
}

}  // namespace flarekit::gl
