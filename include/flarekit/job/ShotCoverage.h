// SPDX-License-Identifier: Apache-2.0
// A light's visibility over a shot: per frame, the mean visibility of its disc in a matte or
// depth pass (raw), then the attack/release filter over the frames before it (filtered), and
// coverage.csv. The filter looks back a fixed number of the shot's frames, starting fresh at
// the first of them, so a frame's value is the same whichever chunk of the shot renders it.
#pragma once

#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/Temporal.h"
#include "flarekit/job/ShotRun.h"

namespace flarekit {

//! What hides the light over a shot (or in one image): a matte, a channel of the plate, or a
//! depth pass against the light's distance.
struct OcclusionOptions {
    std::string matte;         //!< --matte PATTERN (or one file for a single image)
    std::string matteChannel;  //!< --matte-channel NAME (of the matte, else of the input)
    std::string depthChannel;  //!< --depth-channel NAME (of --matte's file, else the input)
    std::optional<float> lightDepth;
    float lightRadius = 8;
    TemporalParams temporal;
    bool enabled() const {
        return !matte.empty() || !matteChannel.empty() || !depthChannel.empty();
    }
};
inline constexpr Param<OcclusionOptions> kOcclusionParams[] = {
    // Up to 10,000 px: a sun disc larger than any frame still has a finite cost (the disc's
    // pixels are visited once).
    param<&OcclusionOptions::lightRadius>(
        "light_radius", 0, 10000, "px",
        "the light's disc in pixels: coverage is the mean visibility over it"),
};
inline constexpr TextParam<OcclusionOptions> kOcclusionTextParams[] = {
    text<&OcclusionOptions::matte>(
        "matte",
        "holdout matte (a frame pattern for a sequence): 1 = foreground hiding the light; its "
        "alpha, or its red channel when it has none (--matte-channel picks); with --depth-channel, "
        "the depth pass"),
    text<&OcclusionOptions::matteChannel>(
        "matte_channel",
        "the matte's channel by name: R, G, B, A or any channel of an EXR (fg.A), of --matte's "
        "file, else of the input itself"),
    text<&OcclusionOptions::depthChannel>(
        "depth_channel",
        "the depth pass's channel by name (Z, depth.Z, R, ...) of --matte's file, else of the "
        "input: a pixel nearer than --light-depth hides the light"),
};
//! The option combinations, checked before any work (a depth channel needs --light-depth, ...).
Status checkOcclusionOptions(const OcclusionOptions& options);

//! A per-frame CSV (coverage.csv, a written track): `rows` (by frame) merged into the rows the
//! file already has under `header` (another chunk's), under a lock on its folder, written
//! atomically.
Status mergeCsvRows(const std::string& path, const std::string& header,
                    const std::map<int, std::string>& rows);

//! One row of coverage.csv.
struct CoverageRow {
    int frame = 0;
    Point position;
    double raw = 1, filtered = 1;
};

class ShotCoverage {
  public:
    //! `lightAt`: the light's position in a frame. `plan` null: a single image (`single`, the
    //! matte file or none), no filter.
    ShotCoverage(const OcclusionOptions& args, const ShotPlan* plan, std::string single,
                 std::function<Point(int)> lightAt, const JobEvents& events = {});
    //! The frame's raw and filtered coverage; `frame`'s plate as read (its size is what a matte
    //! must have; its channels serve when the matte or depth is the plate's own).
    Result<CoverageRow> at(int frame, const LoadedImage& plate);
    //! coverage.csv in the output folder: this run's rows merged into the rows other chunks
    //! wrote (under a lock, so chunks finishing together keep each other's rows).
    Status writeCsv(const std::string& dir, const std::vector<CoverageRow>& rows) const;

  private:
    //! `current`: the frame being rendered, whose plate is `plate`.
    Result<double> raw(int frame, int current, const LoadedImage& plate);

    OcclusionOptions m_args;
    const ShotPlan* m_plan;
    std::optional<FramePattern> m_mattePattern;
    std::string m_single;
    JobEvents m_events;
    std::function<Point(int)> m_lightAt;
    //! Frames the filter looks back: its slowest time constant decays to 1e-4 over them.
    int m_lookBack = 0;
    std::mutex m_mutex;
    std::map<int, double> m_raw;  //!< cache: frames the look-back of several frames shares
};

}  // namespace flarekit
