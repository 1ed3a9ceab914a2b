// SPDX-License-Identifier: Apache-2.0
// flarekit demo: the built-in drive (road, trees, buildings, tunnel, turn) rendered to PNG
// frames, a coverage log, a strip of six frames and, with ffmpeg installed, an MP4.
// PNG encoding runs on a writer thread so the GL/raycast/flare work of the next frame overlaps it.
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

#include <pthread.h>
#include <sched.h>
#include <sys/statvfs.h>

#include "Common.h"
#include "ParamOptions.h"
#include "Progress.h"
#include "Video.h"
#include "core/Interrupt.h"
#include "core/Parallel.h"
#include "flarekit/Demo.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Limits.h"
#include "flarekit/gl/DemoAnimation.h"
#include "flarekit/gl/GpuVisibility.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/HeadlessGl.h"
#endif

namespace flarekit::cli {

namespace {

struct DemoArgs {
    std::string outDir, size = "1280x720", preset = kDefaultSpritePreset;
    DemoSettings settings;
    bool noVideo = false;
    bool noFrames = false;  //!< render and time the drive, write nothing (the render stage alone)
};

//! Writes frames in order on its own thread; at most `capacity` frames wait in memory.
class FrameWriter {
  public:
    explicit FrameWriter(std::size_t capacity)
        : m_capacity(capacity), m_thread([this] { run(); }) {}
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
                options.encode = encodeSettings();
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

#if FLAREKIT_HAS_GL
//! Refuses a run whose frames would not fit on the output's file system, before the first
//! frame: the estimate is ~1.5 bytes per pixel per PNG frame (the drive's 720p frames take ~0.3
//! at zlib level 1; busier frames and --png-compression 0 take more), plus the MP4 at most a
//! tenth of that.
Status checkDemoDisk(const DemoArgs& a, int w, int h) {
    // The output directory may not exist yet: its nearest existing ancestor's file system.
    std::filesystem::path dir = std::filesystem::absolute(a.outDir);
    std::error_code ec;
    while (!std::filesystem::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path())
        dir = dir.parent_path();
    struct statvfs fs {};
    if (::statvfs(dir.c_str(), &fs) != 0) return Ok{};  // unknown: the writes will tell
    const double frames = double(a.settings.frames > 0 ? a.settings.frames : 240);
    const double need = frames * double(w) * double(h) * 1.5 * (a.noVideo ? 1.0 : 1.1);
    const double freeBytes = double(fs.f_bavail) * double(fs.f_frsize);
    if (need <= freeBytes) return Ok{};
    return invalidInput(a.outDir + ": the demo needs an estimated " + formatBytes(need) +
                        " of disk (" + std::to_string(int(frames)) + " frames at " +
                        std::to_string(w) + "x" + std::to_string(h) + ", ~1.5 bytes per pixel), " +
                        formatBytes(freeBytes) + " free there: lower --frames or --size");
}

int runDemo(DemoArgs& a) {
    const auto size = parseSize(a.size);
    if (!size)
        return report(
            invalidInput("--size: expected WIDTHxHEIGHT, e.g. 1280x720, got '" + a.size + "'"));
    const auto [w, h] = *size;
    a.settings.width = w;
    a.settings.height = h;
    if (Status s = validateDemoSettings(a.settings); !s) return report(s.error());
    auto preset = loadPreset(a.preset);
    if (!preset) return report(preset.error());
    if (Status s = checkFlareWork(*preset, w, h, 1, a.preset); !s) return report(s.error());
    auto gl = createHeadlessGl();
    if (!gl) return report(gl.error());
    if (Status s = checkGlFrame(w, h, a.settings.msaaSamples, "--size"); !s)
        return report(s.error());
    if (Status s = checkDemoDisk(a, w, h); !s) return report(s.error());
    if (Status s = makeOutputDirectory(a.outDir); !s) return report(s.error());
    auto demo = DemoAnimation::create(a.settings, *preset);
    if (!demo) return report(demo.error());

    const int n = demo->frameCount();
    const int digits = std::max(4, int(std::to_string(n).size()));
    const std::string dir = std::filesystem::path(a.outDir).string() + "/";
    auto framePath = [&](int i) {
        std::string number = std::to_string(i + 1);
        number.insert(0, std::size_t(digits) - std::min(number.size(), std::size_t(digits)), '0');
        return dir + "frame_" + number + ".png";
    };
    std::printf("demo: %d frames at %dx%d, %zu objects, method %s, %s via %s\n", n, w, h,
                demo->primitiveCount(), a.settings.method.c_str(), (*gl)->renderer().c_str(),
                (*gl)->platform().c_str());
    std::fflush(stdout);

    std::string csv =
        "frame,time_s,coverage_raw,coverage_smoothed,in_frame,edge_fade,exposure,sun_x,sun_y,"
        "flare_intensity,render_ms,visibility_ms,flare_ms\n";
    double renderMs = 0, visibilityMs = 0, flareMs = 0;
    Strip strip(n, w, h);
    FrameWriter writer(3);
    Progress progress("demo", n);
    //! What an interrupt leaves: the complete frames, in order, and nothing else.
    auto stopped = [&] {
        progress.finish();
        (void)writer.close();
        const int done = writer.written();
        return report(interruptedError(
            done == 0 ? "no frame was written"
                      : std::to_string(done) + " of " + std::to_string(n) + " frames written (" +
                            framePath(0) + " .. " + framePath(done - 1) +
                            ", all complete); no coverage.csv, strip or video"));
    };
    for (int i = 0; i < n; ++i) {
        if (interrupted()) return stopped();
        auto frame = demo->next();
        if (!frame) {
            progress.finish();
            (void)writer.close();
            return report(frame.error());
        }
        char line[256];
        std::snprintf(line, sizeof line,
                      "%d,%.4f,%.5f,%.5f,%.4f,%.4f,%.4f,%.2f,%.2f,%.4f,%.2f,%.2f,%.2f\n", i + 1,
                      frame->time, frame->rawCoverage, frame->temporal.coverage, frame->inFrame,
                      frame->temporal.edgeFade, frame->temporal.exposure, double(frame->sunPixel.x),
                      double(frame->sunPixel.y), double(frame->flareIntensity), frame->renderMs,
                      frame->visibilityMs, frame->flareMs);
        csv += line;
        renderMs += frame->renderMs;
        visibilityMs += frame->visibilityMs;
        flareMs += frame->flareMs;
        if (!a.noFrames) {
            strip.offer(i, frame->image);
            writer.push(framePath(i), std::move(frame->image));
        }
        progress.update(i + 1);
    }
    if (interrupted()) return stopped();
    progress.finish();
    if (Status s = writer.close(); !s) return report(s.error());
    if (a.noFrames) {
        std::printf(
            "demo: per frame %.1f ms render, %.1f ms visibility (%s), %.1f ms flare + "
            "tone map (--no-frames: nothing written)\n",
            renderMs / n, visibilityMs / n, a.settings.method.c_str(), flareMs / n);
        return kExitOk;
    }
    if (Status s = writeText(dir + "coverage.csv", csv); !s) return report(s.error());
    WriteOptions stripOptions;
    stripOptions.encode = encodeSettings();
    if (Status s = writeImage(dir + "strip.png", strip.image(), stripOptions); !s)
        return report(s.error());
    std::printf(
        "demo: per frame %.1f ms render, %.1f ms visibility (%s), %.1f ms flare + tone map\n",
        renderMs / n, visibilityMs / n, a.settings.method.c_str(), flareMs / n);
    std::printf("demo: frames %s .. %s, log %scoverage.csv, strip %sstrip.png\n",
                framePath(0).c_str(), framePath(n - 1).c_str(), dir.c_str(), dir.c_str());
    if (a.noVideo) return kExitOk;
    const std::string ffmpeg = findFfmpeg();
    if (ffmpeg.empty()) {
        warn("ffmpeg is not installed: no MP4 (the PNG frames are written)");
        return kExitOk;
    }
    const double fps = a.settings.fps;
    char pattern[64];
    std::snprintf(pattern, sizeof pattern, "frame_%%0%dd.png", digits);
    if (Status s = encodeVideo(ffmpeg, dir + pattern, fps, dir + "demo.mp4", dir + "ffmpeg.log");
        !s) {
        return report(s.error());
    }
    std::error_code ec;
    std::filesystem::remove(dir + "ffmpeg.log", ec);  // empty on success; kept only on failure
    std::printf("demo: video %sdemo.mp4 (%.3g fps)\n", dir.c_str(), fps);
    return kExitOk;
}

#else
int runDemo(DemoArgs&) {
    return report(builtWithoutGl("demo"));
}
#endif
}  // namespace

void addDemoCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<DemoArgs>();
    CLI::App* cmd = app.add_subcommand("demo",
                                       "Render the built-in drive (trees, buildings, tunnel, turn) "
                                       "with an occlusion-aware sun flare");
    cmd->add_option("-o,--output", args->outDir, "output directory (created if missing)")
        ->required();
    addParamOption<DemoSettings>(cmd, kDemoParams, "frames", args->settings);
    addParamOption<DemoSettings>(cmd, kDemoParams, "fps", args->settings);
    cmd->add_option("--size", args->size, "frame size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option(
           "--method", args->settings.method,
           "visibility method, one of " + visibilityMethodList() +
               " (raycast: CPU flare; the others: flare, smoothing and tone map on the GPU)")
        ->capture_default_str();
    cmd->add_option("--preset", args->preset, "sprite flare preset (name or JSON file)")
        ->capture_default_str();
    cmd->add_flag(
        "--conditional-render", args->settings.conditionalRender,
        "with --method query: draw the flare under glBeginConditionalRender on the sun's query");
    addParamOption<DemoSettings>(cmd, kDemoParams, "samples", args->settings);
    addParamOption<DemoSettings>(cmd, kDemoParams, "msaa", args->settings);
    addParamOptions<TemporalParams>(cmd, kTemporalParams, args->settings.temporal);
    cmd->add_flag("--no-video", args->noVideo, "skip the MP4 even when ffmpeg is installed");
    cmd->add_flag("--no-frames", args->noFrames,
                  "render and time the drive but write nothing (the render stage's cost without "
                  "the frame writer beside it)");
    cmd->callback([args, &exitCode] { exitCode = runDemo(*args); });
}

}  // namespace flarekit::cli
