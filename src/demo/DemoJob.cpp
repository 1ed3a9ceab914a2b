// SPDX-License-Identifier: Apache-2.0
#include <sys/statvfs.h>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/Parallel.h"
#include "core/SafeWrite.h"
#include "flarekit/Limits.h"
#include "flarekit/gl/DemoAnimation.h"
#include "flarekit/gl/DemoJob.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::gl {

namespace {

//! Writes frames in order on its own thread; at most `capacity` frames wait in memory.
class FrameWriter {
  public:
    FrameWriter(std::size_t capacity, const EncodeSettings& encode)
        : m_capacity(capacity), m_encode(encode), m_thread([this] { run(); }) {}
    ~FrameWriter() { (void)close(); }
    void push(std::string path, Image image) {
        std::unique_lock lock(m_mutex);
        m_cv.wait(lock, [&] { return m_queue.size() < m_capacity; });
        m_queue.emplace_back(std::move(path), std::move(image));
        m_cv.notify_all();
    }
    //! Frames written completely so far (in order: after a failure none are written).
    int written() const { return m_written.load(); }
    //! Waits for every queued frame; the first write error, if any.
    Status close() {
        {
            std::lock_guard lock(m_mutex);
            m_closed = true;
            m_cv.notify_all();
        }
        if (m_thread.joinable()) m_thread.join();
        return m_status;
    }

  private:
    void run() {
        // Below the render stage: the encoder takes the cores the GL driver and the flare leave
        // idle (llvmpipe's threads would otherwise share them with it; the queue bounds the
        // lag). Linux applies a nice value to one thread when given its id; the encode's own
        // parallel loops stay on this thread (runOnThisThread), off the pool's workers.
        sched_param idle{};
        (void)pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle);
        for (;;) {
            std::pair<std::string, Image> job;
            {
                std::unique_lock lock(m_mutex);
                m_cv.wait(lock, [&] { return !m_queue.empty() || m_closed; });
                if (m_queue.empty()) return;
                job = std::move(m_queue.front());
                m_queue.pop_front();
                m_cv.notify_all();
            }
            if (!m_status) continue;  // after a failure, drain without writing
            Status s = Ok{};
            runOnThisThread([&] {
                WriteOptions options;
                options.encode = m_encode;
                s = writeImage(job.first, job.second, options);
            });
            if (!s) {
                m_status = s;
            } else {
                ++m_written;
            }
        }
    }
    std::size_t m_capacity;
    EncodeSettings m_encode;
    std::mutex m_mutex;
    std::condition_variable m_cv;
    std::deque<std::pair<std::string, Image>> m_queue;
    bool m_closed = false;
    Status m_status = Ok{};
    std::atomic<int> m_written{0};
    std::thread m_thread;
};

//! A box-filtered copy `factor` times smaller (strip thumbnails).
Image shrink(const Image& src, int factor) {
    Image out(std::max(1, src.width() / factor), std::max(1, src.height() / factor));
    const float norm = 1.f / float(factor * factor);
    for (int y = 0; y < out.height(); ++y) {
        for (int x = 0; x < out.width(); ++x) {
            Rgba sum{0, 0, 0, 0};
            for (int j = 0; j < factor; ++j) {
                for (int i = 0; i < factor; ++i) {
                    const Rgba& p = src.at(x * factor + i, y * factor + j);
                    sum.r += p.r, sum.g += p.g, sum.b += p.b, sum.a += p.a;
                }
            }
            out.at(x, y) = {sum.r * norm, sum.g * norm, sum.b * norm, sum.a * norm};
        }
    }
    return out;
}

//! Six evenly spaced frames side by side, 3 x 2, each 1/4 size (or less for big frames).
class Strip {
  public:
    Strip(int frames, int width, int height)
        : m_frames(frames), m_factor(std::max(1, width / 320)) {
        m_cellW = width / m_factor;
        m_cellH = height / m_factor;
        m_image = Image(3 * m_cellW, 2 * m_cellH);
    }
    void offer(int index, const Image& frame) {
        for (int k = 0; k < 6; ++k) {
            if (index != pick(k)) continue;
            const Image small = shrink(frame, m_factor);
            for (int y = 0; y < small.height() && y < m_cellH; ++y) {
                for (int x = 0; x < small.width() && x < m_cellW; ++x) {
                    m_image.at((k % 3) * m_cellW + x, (k / 3) * m_cellH + y) = small.at(x, y);
                }
            }
        }
    }
    const Image& image() const { return m_image; }

  private:
    int pick(int k) const { return int(std::lround((k + 0.5) / 6.0 * (m_frames - 1))); }
    int m_frames, m_factor, m_cellW = 0, m_cellH = 0;
    Image m_image;
};

//! Refuses a run whose frames would not fit on the output's file system, before the first
//! frame: the estimate is ~1.5 bytes per pixel per PNG frame (the drive's 720p frames take ~0.3
//! at zlib level 1; busier frames and --png-compression 0 take more), plus the MP4 at most a
//! tenth of that.
Status checkDemoDisk(const DemoJobOptions& a, bool video, int w, int h) {
    // The output directory may not exist yet: its nearest existing ancestor's file system.
    std::filesystem::path dir = std::filesystem::absolute(a.outDir);
    std::error_code ec;
    while (!std::filesystem::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path())
        dir = dir.parent_path();
    struct statvfs fs {};
    if (::statvfs(dir.c_str(), &fs) != 0) return Ok{};  // unknown: the writes will tell
    const double frames = double(a.settings.frames > 0 ? a.settings.frames : 240);
    const double need = frames * double(w) * double(h) * 1.5 * (video ? 1.1 : 1.0);
    const double freeBytes = double(fs.f_bavail) * double(fs.f_frsize);
    if (need <= freeBytes) return Ok{};
    return invalidInput(a.outDir + ": the demo needs an estimated " + formatBytes(need) +
                        " of disk (" + std::to_string(int(frames)) + " frames at " +
                        std::to_string(w) + "x" + std::to_string(h) + ", ~1.5 bytes per pixel), " +
                        formatBytes(freeBytes) + " free there: lower --frames or --size");
}

//! The coverage log's row of one frame.
std::string csvRow(int index, const DemoFrame& f) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%d,%.4f,%.5f,%.5f,%.4f,%.4f,%.4f,%.2f,%.2f,%.4f,%.2f,%.2f,%.2f\n", index + 1,
                  f.time, f.rawCoverage, f.temporal.coverage, f.inFrame, f.temporal.edgeFade,
                  f.temporal.exposure, double(f.sunPixel.x), double(f.sunPixel.y),
                  double(f.flareIntensity), f.renderMs, f.visibilityMs, f.flareMs);
    return line;
}

}  // namespace

std::string DemoReport::framePath(const DemoJobOptions& options, int index) const {
    std::string number = std::to_string(index + 1);
    number.insert(0, std::size_t(digits) - std::min(number.size(), std::size_t(digits)), '0');
    return std::filesystem::path(options.outDir).string() + "/frame_" + number + ".png";
}

Result<DemoReport> runDemoJob(const DemoJobOptions& a, const JobEvents& events) {
    const int w = a.settings.width, h = a.settings.height;
    if (Status s = validateDemoSettings(a.settings); !s) return s.error();
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    if (Status s = checkFlareWork(*preset, w, h, 1, a.preset); !s) return s.error();
    auto gl = createQuietHeadlessGl();
    if (!gl) return gl.error();
    if (Status s = checkGlFrame(w, h, a.settings.msaaSamples, "--size"); !s) return s.error();
    if (Status s = checkDemoDisk(a, a.reserveVideo, w, h); !s) return s.error();
    if (Status s = makeOutputDirectory(a.outDir); !s) return s.error();
    auto demo = DemoAnimation::create(a.settings, *preset);
    if (!demo) return demo.error();

    DemoReport report;
    report.frames = demo->frameCount();
    report.digits = std::max(4, int(std::to_string(report.frames).size()));
    report.renderer = (*gl)->renderer();
    report.platform = (*gl)->platform();
    const int n = report.frames;
    char line[400];
    std::snprintf(line, sizeof line, "demo: %d frames at %dx%d, %zu objects, method %s, %s via %s",
                  n, w, h, demo->primitiveCount(), a.settings.method.c_str(),
                  report.renderer.c_str(), report.platform.c_str());
    events.say(line);

    std::string csv =
        "frame,time_s,coverage_raw,coverage_smoothed,in_frame,edge_fade,exposure,sun_x,sun_y,"
        "flare_intensity,render_ms,visibility_ms,flare_ms\n";
    Strip strip(n, w, h);
    FrameWriter writer(3, a.encode);
    //! What a cancel leaves: the complete frames, in order, and nothing else.
    auto stopped = [&]() -> Error {
        (void)writer.close();
        const int done = writer.written();
        const std::string what = done == 0 ? "no frame was written"
                                           : std::to_string(done) + " of " + std::to_string(n) +
                                                 " frames written (" + report.framePath(a, 0) +
                                                 " .. " + report.framePath(a, done - 1) +
                                                 ", all complete); no coverage.csv, strip or video";
        return cancelledError(what);
    };
    for (int i = 0; i < n; ++i) {
        if (events.stopRequested()) return stopped();
        auto frame = demo->next();
        if (!frame) {
            (void)writer.close();
            return frame.error();
        }
        csv += csvRow(i, *frame);
        report.renderMs += frame->renderMs / n;
        report.visibilityMs += frame->visibilityMs / n;
        report.flareMs += frame->flareMs / n;
        if (!a.noFrames) {
            strip.offer(i, frame->image);
            writer.push(report.framePath(a, i), std::move(frame->image));
        }
        if (events.progress) events.progress(i + 1, n);
    }
    if (events.stopRequested()) return stopped();
    if (Status s = writer.close(); !s) return s.error();
    if (a.noFrames) return report;
    const std::string dir = std::filesystem::path(a.outDir).string() + "/";
    if (Status s = writeFileSafely(dir + "coverage.csv", csv); !s) return s.error();
    WriteOptions stripOptions;
    stripOptions.encode = a.encode;
    if (Status s = writeImage(dir + "strip.png", strip.image(), stripOptions); !s) return s.error();
    return report;
}

}  // namespace flarekit::gl
