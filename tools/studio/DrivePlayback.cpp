// SPDX-License-Identifier: Apache-2.0
#include "DrivePlayback.h"

#include <cstdio>

#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/Limits.h"
#include "flarekit/gl/DemoAnimation.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::studio {

Result<std::unique_ptr<DrivePlayback>> DrivePlayback::start(const DemoSettings& settings,
                                                            const Preset& preset) {
    if (Status s = validateDemoSettings(settings); !s) return s.error();
    // The kept frames: 8-bit RGBA each, within a quarter of the memory budget.
    const double bytes = 4.0 * settings.width * settings.height * settings.frames;
    const double budget = double(resourceLimits().maxMemoryBytes) / 4;
    if (bytes > budget)
        return invalidInput(
            "drive: " + std::to_string(settings.frames) + " frames of " +
            std::to_string(settings.width) + "x" + std::to_string(settings.height) + " need " +
            std::to_string(int(bytes / 1048576)) + " MiB kept, over the studio's " +
            std::to_string(int(budget / 1048576)) + " MiB: fewer frames or a smaller size");
    return std::unique_ptr<DrivePlayback>(new DrivePlayback(settings, preset));
}

DrivePlayback::DrivePlayback(const DemoSettings& settings, const Preset& preset)
    : m_settings(settings), m_preset(preset) {
    m_settings.methodViews = true;  // read back after each frame: a few small textures
    m_thread = std::thread([this] { work(); });
}

DrivePlayback::~DrivePlayback() {
    m_stop = true;
    if (m_thread.joinable()) m_thread.join();
}

void DrivePlayback::work() {
    const auto fail = [this](const std::string& message) {
        std::lock_guard lock(m_mutex);
        m_error = message;
    };
    // The frames are made on this thread alone (its own GL context; the pipeline's CPU loops
    // kept off the cores the window's view updates on).
    runOnThisThread([&] {
        auto context = gl::createFrameContext(m_settings.width, m_settings.height,
                                              m_settings.msaaSamples, "drive");
        if (!context) return fail(context.error().message);
        auto drive = DemoAnimation::create(m_settings, m_preset);
        if (!drive) return fail(drive.error().message);
        for (int i = 0; i < m_settings.frames && !m_stop; ++i) {
            auto f = drive->next();
            if (!f) return fail(f.error().message);
            DriveFrame kept;
            kept.image = {f->image.width(), f->image.height(), 4, {}};
            kept.image.pixels.resize(f->image.pixelCount() * 4);
            encodeSrgb8(f->image.data(), f->image.pixelCount(), 4, kept.image.pixels.data());
            for (std::size_t p = 3; p < kept.image.pixels.size(); p += 4)
                kept.image.pixels[p] = 255;
            kept.time = f->time, kept.rawCoverage = f->rawCoverage;
            kept.filteredCoverage = f->temporal.coverage, kept.inFrame = f->inFrame;
            kept.sun = f->sunPixel, kept.sunInFront = f->sunInFront;
            for (const MethodView& view : f->methodViews)
                kept.methodViews.push_back(methodPicture(view));
            {
                std::lock_guard lock(m_mutex);
                m_frames.push_back(std::move(kept));
            }
            ++m_ready;
        }
    });
    m_finished = true;
}

std::string DrivePlayback::error() const {
    std::lock_guard lock(m_mutex);
    return m_error;
}

DriveFrame DrivePlayback::frame(int i) const {
    std::lock_guard lock(m_mutex);
    return m_frames.at(std::size_t(i));
}

void DrivePlayback::coverage(std::vector<float>& raw, std::vector<float>& filtered) const {
    std::lock_guard lock(m_mutex);
    raw.clear(), filtered.clear();
    for (const DriveFrame& f : m_frames)
        raw.push_back(float(f.rawCoverage)), filtered.push_back(float(f.filteredCoverage));
}

std::string DrivePlayback::coverageCsv() const {
    std::lock_guard lock(m_mutex);
    std::string csv = "frame,time_s,coverage_raw,coverage_smoothed,in_frame\n";
    char line[160];
    for (std::size_t i = 0; i < m_frames.size(); ++i) {
        const DriveFrame& f = m_frames[i];
        std::snprintf(line, sizeof line, "%zu,%.4f,%.5f,%.5f,%.4f\n", i + 1, f.time, f.rawCoverage,
                      f.filteredCoverage, f.inFrame);
        csv += line;
    }
    return csv;
}

}  // namespace flarekit::studio
