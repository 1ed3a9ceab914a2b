#include "ShotCoverage.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ParamOptions.h"

namespace flarekit::cli {

namespace {
std::optional<int> channelIndex(const std::string& name) {
    if (name == "R" || name == "r") return 0;
    if (name == "G" || name == "g") return 1;
    if (name == "B" || name == "b") return 2;
    if (name == "A" || name == "a") return 3;
    return std::nullopt;
}

//! The ln(1e4) time constants after which a step's weight is under 1e-4 of a value.
constexpr double kLookBackDecays = 9.2103403719761836;
}  // namespace

void addOcclusionOptions(CLI::App* cmd, OcclusionArgs& args) {
    cmd->add_option("--matte", args.matte,
                    "holdout matte (a frame pattern for a sequence): 1 = foreground hiding the "
                    "light; its alpha, or its red channel when it has none (--matte-channel "
                    "picks); with --depth-channel, the depth pass");
    cmd->add_option("--matte-channel", args.matteChannel,
                    "R, G, B or A: the matte's channel (of --matte, else of the input itself)")
        ->check(CLI::IsMember({"R", "G", "B", "A", "r", "g", "b", "a"}));
    cmd->add_option("--depth-channel", args.depthChannel,
                    "R, G, B or A of the depth pass (--matte's file, else the input): a pixel "
                    "nearer than --light-depth hides the light");
    cmd->add_option("--light-depth", args.lightDepth,
                    "the light's distance, in the depth pass's units");
    cmd->add_option("--light-radius", args.lightRadius,
                    "the light's disc in pixels: coverage is the mean visibility over it")
        ->check(CLI::Range(0.0, 10000.0))
        ->capture_default_str();
    addParamOptions<TemporalParams>(cmd, std::span(kTemporalParams).first(3), args.temporal);
}

Status checkOcclusionArgs(const OcclusionArgs& a) {
    if (!a.depthChannel.empty()) {
        if (!channelIndex(a.depthChannel))
            return invalidInput("--depth-channel " + a.depthChannel +
                                ": flarekit reads the R, G, B and A channels of a file; split a "
                                "depth channel into its own file first (oiiotool IN --ch Z -o "
                                "depth.exr) and give it with --matte, --depth-channel R");
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

ShotCoverage::ShotCoverage(const OcclusionArgs& args, const ShotPlan* plan, std::string single,
                           std::function<Point(int)> lightAt)
    : m_args(args), m_plan(plan), m_single(std::move(single)), m_lightAt(std::move(lightAt)) {
    if (plan && !args.matte.empty()) m_mattePattern = *parseFramePattern(args.matte);
    if (plan) {
        const double tau = std::max(args.temporal.attackSeconds, args.temporal.releaseSeconds);
        m_lookBack = int(std::ceil(kLookBackDecays * tau * plan->fps));
    }
}

Result<double> ShotCoverage::raw(int frame, int current, const Image& image) {
    {
        std::lock_guard lock(m_mutex);
        if (auto it = m_raw.find(frame); it != m_raw.end()) return it->second;
    }
    // The occluding pixels: the matte file, else the input itself (the frame being rendered, or
    // an earlier one of the look-back, read again).
    std::optional<LoadedImage> loaded;
    std::string path;
    if (!m_args.matte.empty())
        path = m_mattePattern ? m_mattePattern->path(frame) : m_single;
    else if (frame != current)
        path = m_plan->in.path(frame);
    if (!path.empty()) {
        auto read = readInputImage(path, {});
        if (!read) return read.error();
        if (read->image.width() != image.width() || read->image.height() != image.height())
            return invalidInput(path + ": " + std::to_string(read->image.width()) + "x" +
                                std::to_string(read->image.height()) + ", but the frame " +
                                std::to_string(current) + " it must match is " +
                                std::to_string(image.width()) + "x" +
                                std::to_string(image.height()));
        loaded = std::move(*read);
    }
    Occluder occluder;
    if (!m_args.depthChannel.empty()) {
        occluder.channel = *channelIndex(m_args.depthChannel);
        occluder.lightDepth = m_args.lightDepth;
    } else if (!m_args.matteChannel.empty()) {
        occluder.channel = *channelIndex(m_args.matteChannel);
    } else {
        occluder.channel = loaded && !loaded->hasAlpha ? 0 : 3;  // a grey matte: its value
    }
    const double v = discVisibility(loaded ? loaded->image : image, occluder, m_lightAt(frame),
                                    m_args.lightRadius);
    std::lock_guard lock(m_mutex);
    m_raw[frame] = v;
    return v;
}

Result<CoverageRow> ShotCoverage::at(int frame, const Image& image) {
    CoverageRow row{frame, m_lightAt(frame), 1, 1};
    auto now = raw(frame, frame, image);
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
        auto value = *it == frame ? now : raw(*it, frame, image);
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
    if (dir.empty()) dir = ".";
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
    Status s = writeText(path, text);
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

}  // namespace flarekit::cli
