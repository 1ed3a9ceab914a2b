// SPDX-License-Identifier: Apache-2.0
#include "flarekit/job/ShotCoverage.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/SafeWrite.h"

namespace flarekit {

namespace {
//! The ln(1e4) time constants after which a step's weight is under 1e-4 of a value.
constexpr double kLookBackDecays = 9.2103403719761836;
}  // namespace

Status checkOcclusionOptions(const OcclusionOptions& a) {
    if (!a.depthChannel.empty()) {
        if (!a.lightDepth)
            return invalidInput("--depth-channel needs --light-depth (the light's distance)");
        if (!a.matteChannel.empty())
            return invalidInput("--depth-channel and --matte-channel: give one of them");
    } else if (a.lightDepth) {
        return invalidInput("--light-depth needs --depth-channel");
    }
    if (a.lightDepth && !std::isfinite(*a.lightDepth))
        return invalidInput("--light-depth: expected a finite number");
    return validateTemporalParams(a.temporal);
}

ShotCoverage::ShotCoverage(const OcclusionOptions& args, const ShotPlan* plan, std::string single,
                           std::function<Point(int)> lightAt, const JobEvents& events)
    : m_args(args),
      m_plan(plan),
      m_single(std::move(single)),
      m_events(events),
      m_lightAt(std::move(lightAt)) {
    if (plan && !args.matte.empty()) m_mattePattern = *parseFramePattern(args.matte);
    if (plan) {
        const double tau = std::max(args.temporal.attackSeconds, args.temporal.releaseSeconds);
        m_lookBack = int(std::ceil(kLookBackDecays * tau * plan->fps));
    }
}

Result<double> ShotCoverage::raw(int frame, int current, const LoadedImage& plate) {
    {
        std::lock_guard lock(m_mutex);
        if (auto it = m_raw.find(frame); it != m_raw.end()) return it->second;
    }
    // The occluding pixels: the matte file, else the plate itself (the frame being rendered, or
    // an earlier one of the look-back, read again).
    std::optional<LoadedImage> read;
    std::string path = frame == current ? "" : m_plan->in.path(frame);
    if (!m_args.matte.empty()) path = m_mattePattern ? m_mattePattern->path(frame) : m_single;
    if (!path.empty()) {
        auto loaded = readJobInput(path, {}, m_events);
        if (!loaded) return loaded.error();
        const Image& m = loaded->image;
        if (m.width() != plate.image.width() || m.height() != plate.image.height())
            return invalidInput(
                path + ": " + std::to_string(m.width()) + "x" + std::to_string(m.height()) +
                ", but the frame " + std::to_string(current) + " it must match is " +
                std::to_string(plate.image.width()) + "x" + std::to_string(plate.image.height()));
        read = std::move(*loaded);
    }
    const LoadedImage& source = read ? *read : plate;
    Occluder occluder;  // channel 3: the plane below goes into alpha
    std::string channel = m_args.matteChannel;
    if (!m_args.depthChannel.empty()) {
        channel = m_args.depthChannel;
        occluder.lightDepth = m_args.lightDepth;
    } else if (channel.empty()) {
        // A grey matte: its value. (One character assigned: GCC 12 warns falsely on a literal.)
        channel.assign(1, read && !read->hasAlpha ? 'R' : 'A');
    }
    const std::string name = !path.empty() ? path : m_plan ? m_plan->in.path(frame) : "the input";
    auto plane = channelByName(source, channel, name);
    if (!plane) return plane.error();
    Image values(source.image.width(), source.image.height());
    for (std::size_t i = 0; i < plane->size(); ++i) values.data()[4 * i + 3] = (*plane)[i];
    const double v = discVisibility(values, occluder, m_lightAt(frame), m_args.lightRadius);
    std::lock_guard lock(m_mutex);
    m_raw[frame] = v;
    return v;
}

Result<CoverageRow> ShotCoverage::at(int frame, const LoadedImage& plate) {
    const Image& image = plate.image;
    CoverageRow row{frame, m_lightAt(frame), 1, 1};
    auto now = raw(frame, frame, plate);
    if (!now) return now.error();
    row.raw = row.filtered = *now;
    if (!m_plan) return row;
    // The filter runs over the shot's frames from `lookBack` before this one, fresh at the
    // first: the same frames and steps for this frame in every chunking of the shot.
    const auto& shot = m_plan->shotFrames;
    auto first = std::lower_bound(shot.begin(), shot.end(), frame - m_lookBack);
    TemporalParams params = m_args.temporal;
    params.guardBand = 0;
    TemporalFilter filter(params);
    std::optional<int> previous;
    for (auto it = first; it != shot.end() && *it <= frame; ++it) {
        auto value = *it == frame ? now : raw(*it, frame, plate);
        if (!value) return value.error();
        const double dt = previous ? (*it - *previous) / m_plan->fps : 0.0;
        row.filtered =
            filter.update(*value, m_lightAt(*it), true, image.width(), image.height(), dt).coverage;
        previous = *it;
    }
    return row;
}

Status mergeCsvRows(const std::string& path, const std::string& header,
                    const std::map<int, std::string>& rows) {
    // Chunks of one shot on a farm can finish at once: the merge is done under an exclusive
    // lock on the file's folder (no lock file to leave behind), so no chunk's rows are lost to
    // another's rename.
    std::string dir = std::filesystem::path(path).parent_path().string();
    if (dir.empty()) dir.assign(1, '.');
    const int lockFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lockFd >= 0) ::flock(lockFd, LOCK_EX);
    std::map<int, std::string> lines;
    {
        std::ifstream in(path);
        std::string line;
        if (std::getline(in, line) && line == header)
            while (std::getline(in, line))
                if (!line.empty()) lines[std::atoi(line.c_str())] = line;
    }
    for (const auto& [frame, line] : rows) lines[frame] = line;
    std::string text = header + "\n";
    for (const auto& [frame, line] : lines) text += line + "\n";
    Status s = writeFileSafely(path, text);
    if (lockFd >= 0) ::close(lockFd);  // releases the lock
    return s;
}

Status ShotCoverage::writeCsv(const std::string& dir, const std::vector<CoverageRow>& rows) const {
    std::map<int, std::string> lines;
    for (const CoverageRow& r : rows) {
        char line[200];
        // %.9g: floats written and read back are the same; 0.5 px is the pixel centre.
        std::snprintf(line, sizeof line, "%d,%.9g,%.9g,%.9g,%.9g", r.frame, double(r.position.x),
                      double(r.position.y), r.raw, r.filtered);
        lines[r.frame] = line;
    }
    return mergeCsvRows((std::filesystem::path(dir) / "coverage.csv").string(),
                        "frame,x,y,coverage,filtered_coverage", lines);
}

}  // namespace flarekit
