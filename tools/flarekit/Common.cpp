// SPDX-License-Identifier: Apache-2.0
#include "Common.h"

#include "ShotRun.h"

#include "core/FirstLine.h"
#include "core/Interrupt.h"
#include "core/SafeWrite.h"
#include "flarekit/Limits.h"
#if FLAREKIT_HAS_GL
#include <epoxy/gl.h>
#endif

#include <unistd.h>
#include <charconv>
#include <chrono>
#include <cmath>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <mutex>

namespace flarekit::cli {

namespace {
bool g_interruptReported = false;
}

int report(const Error& error) {
    std::fprintf(stderr, "flarekit: %s\n", cappedLine(error.message).c_str());
    if (error.code == ErrorCode::Interrupted) {
        g_interruptReported = true;
        return 128 + interruptSignal();
    }
    return error.code == ErrorCode::Internal ? kExitInternal : kExitBadInput;
}

int finishProcess(int exitCode) {
    if (interrupted()) {
        // One line in all: a command that failed for another reason has said so already.
        if (!g_interruptReported && exitCode == kExitOk) {
            std::fprintf(stderr, "flarekit: interrupted by %s: %s\n", interruptSignalName().c_str(),
                         "the command had finished; its outputs are complete");
        }
        (void)flushStandardOutput();
        return 128 + interruptSignal();
    }
    if (Status s = flushStandardOutput(); !s && exitCode == kExitOk) return report(s.error());
    return exitCode;
}

std::string excerptLine(const std::string& text, std::size_t max) {
    return excerpt(std::string_view(text).substr(0, text.find('\n')), max);
}

std::string cappedLine(const std::string& message) {
    // 1,000 characters: the longest real message (a list of every known key) fits; a hostile
    // input that echoes megabytes of itself does not reach the terminal.
    return excerptLine(message, 1000);
}

void warn(const std::string& message) {
    std::fprintf(stderr, "flarekit: warning: %s\n", message.c_str());
}

namespace {
//! The one capture of stderr that every live filter shares: file descriptor 2 is the process's,
//! so filters alive at once on several threads (a shot's frames read in parallel) must not each
//! swap it, or the last to finish would restore another's capture. The first filter starts the
//! capture, the last ends it and replays it, dropping what any of them dropped.
struct SharedCapture {
    std::mutex mutex;
    int users = 0;
    std::FILE* file = nullptr;
    int saved = -1;
    std::vector<std::string> dropped;
};
SharedCapture& sharedCapture() {
    static SharedCapture capture;
    return capture;
}
}  // namespace

LibraryNoiseFilter::LibraryNoiseFilter(std::vector<std::string> dropped)
    : m_dropped(std::move(dropped)) {
    SharedCapture& c = sharedCapture();
    std::lock_guard lock(c.mutex);
    c.dropped.insert(c.dropped.end(), m_dropped.begin(), m_dropped.end());
    m_active = true;
    if (c.users++ > 0) return;
    std::fflush(stderr);
    c.file = std::tmpfile();
    if (!c.file) return;
    c.saved = ::dup(STDERR_FILENO);
    if (c.saved < 0 || ::dup2(::fileno(c.file), STDERR_FILENO) < 0) {
        if (c.saved >= 0) ::close(c.saved);
        c.saved = -1;
        std::fclose(c.file);
        c.file = nullptr;
    }
}

std::string LibraryNoiseFilter::finish() {
    if (!m_active) return m_firstDropped;
    m_active = false;
    SharedCapture& c = sharedCapture();
    std::lock_guard lock(c.mutex);
    if (--c.users > 0 || !c.file) {
        if (c.users == 0) c.dropped.clear();
        return m_firstDropped;
    }
    std::fflush(stderr);
    ::dup2(c.saved, STDERR_FILENO);
    ::close(c.saved);
    c.saved = -1;
    std::rewind(c.file);
    char line[4096];
    while (std::fgets(line, sizeof line, c.file)) {
        bool drop = false;
        for (const std::string& prefix : c.dropped)
            drop = drop || std::strncmp(line, prefix.c_str(), prefix.size()) == 0;
        if (!drop) {
            std::fputs(line, stderr);
        } else if (m_firstDropped.empty()) {
            m_firstDropped = line;
            while (!m_firstDropped.empty() &&
                   (m_firstDropped.back() == '\n' || m_firstDropped.back() == ' '))
                m_firstDropped.pop_back();
        }
    }
    std::fclose(c.file);
    c.file = nullptr;
    c.dropped.clear();
    return m_firstDropped;
}

LibraryNoiseFilter::~LibraryNoiseFilter() {
    (void)finish();
}

#if FLAREKIT_HAS_GL
Result<std::unique_ptr<gl::HeadlessGl>> createHeadlessGl() {
    LibraryNoiseFilter filter(
        {"libEGL warning", "MESA-LOADER", "MESA:", "libGL error", "pci id", "\n"});
    auto gl = gl::HeadlessGl::create();
    const std::string mesa = filter.finish();
    if (gl || mesa.empty()) return gl;
    Error e = gl.error();
    e.message += "; Mesa: " + excerptLine(mesa, 160);
    return e;
}

Status checkGlFrame(int width, int height, int msaa, const std::string& field) {
    GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0}, fbWidth = 0, fbHeight = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &fbWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &fbHeight);
    // Each axis against every limit that bounds it (0: a limit the context does not report).
    struct Axis {
        int size;
        const char* side;
        GLint viewport, framebuffer;
        const char* framebufferName;
    };
    for (const Axis& a :
         {Axis{width, "width", viewport[0], fbWidth, "GL_MAX_FRAMEBUFFER_WIDTH"},
          Axis{height, "height", viewport[1], fbHeight, "GL_MAX_FRAMEBUFFER_HEIGHT"}}) {
        const std::pair<GLint, const char*> limits[] = {{texture, "GL_MAX_TEXTURE_SIZE"},
                                                        {renderbuffer, "GL_MAX_RENDERBUFFER_SIZE"},
                                                        {a.viewport, "GL_MAX_VIEWPORT_DIMS"},
                                                        {a.framebuffer, a.framebufferName}};
        for (const auto& [limit, name] : limits) {
            if (limit > 0 && a.size > limit) {
                return invalidInput(field + "." + a.side + ": " + std::to_string(a.size) +
                                    " is over this OpenGL's limit of " + std::to_string(limit) +
                                    " (" + name + ")");
            }
        }
    }
    // Per pixel: the HDR colour, depth and transmittance targets and their resolve (~32 bytes),
    // the read-back and the CPU image (32), 12 per extra MSAA sample; 256 MiB of process and
    // driver (Mesa's llvmpipe measured at ~250 MiB resident with a small frame).
    const double pixels = double(width) * double(height);
    return checkMemory(field, 256.0 * (1 << 20) + pixels * (64.0 + 12.0 * std::max(0, msaa - 1)),
                       std::to_string(width) + "x" + std::to_string(height) + " with " +
                           std::to_string(std::max(1, msaa)) + " sample(s) per pixel");
}
#endif

std::optional<Point> parsePoint(const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    auto number = [](const std::string& s) -> std::optional<float> {
        float v = 0;
        const char* end = s.data() + s.size();
        auto [ptr, ec] = std::from_chars(s.data(), end, v);
        if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
        return v;
    };
    auto x = number(text.substr(0, comma)), y = number(text.substr(comma + 1));
    if (!x || !y) return std::nullopt;
    return Point{*x, *y};
}

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    auto number = [](const char* begin, const char* end) -> std::optional<int> {
        int v = 0;
        auto [ptr, ec] = std::from_chars(begin, end, v);
        if (ec != std::errc() || ptr != end || begin == end) return std::nullopt;
        return v;
    };
    auto w = number(text.data(), text.data() + x),
         h = number(text.data() + x + 1, text.data() + text.size());
    if (!w || !h) return std::nullopt;
    return std::pair{*w, *h};
}

Result<LoadedImage> readInputImage(const std::string& path, const JobMemory& job) {
    const auto start = std::chrono::steady_clock::now();
    auto loaded = [&] {
        LibraryNoiseFilter filter;
        return readImage(path, job);
    }();
    addReadSeconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!loaded) return loaded.error();
    if (loaded->droppedChannels > 0) {
        return invalidInput(
            path + ": " + std::to_string(loaded->fileChannels) +
            " channels; flarekit reads 1 to 4 (grey, grey+alpha, RGB, RGBA): split the others off "
            "first, e.g. oiiotool IN --ch R,G,B,A -o rgba.exr");
    }
    if (loaded->nonFinite > 0)
        warn(path + ": " + std::to_string(loaded->nonFinite) + " NaN/Inf values replaced by 0");
    return loaded;
}

std::shared_ptr<const ExrExtras> keptExtras(const LoadedImage& loaded, const std::string& in,
                                            const std::string& out) {
    if (!loaded.exrExtras) return nullptr;
    std::string ext = std::filesystem::path(out).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".exr" && loaded.extraChannels > 0)
        warn(in + ": its " + std::to_string(loaded.extraChannels) +
             " channel(s) past RGBA go only to an EXR output, not to " + out);
    return loaded.exrExtras;
}

namespace {
template <class T, class Write>
int runWriteJob(const std::string& out, const std::function<Result<T>()>& work,
                const Write& write) {
    if (Status s = checkOutputPath(out); !s) return report(s.error());
    auto result = work();
    if (!result) return report(result.error());
    if (Status s = write(*result); !s) return report(s.error());
    return kExitOk;
}
}  // namespace

int runImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work) {
    return runWriteJob(out, work,
                       [&](const ImageOutput& o) { return writeImage(out, o.image, o.options); });
}

int runImage8Job(const std::string& out, const std::function<Result<Image8>()>& work) {
    return runWriteJob(out, work, [&](const Image8& image) { return writeImage8(out, image); });
}

Error builtWithoutGl(const std::string& what) {
    return invalidInput(what +
                        ": this flarekit was built without OpenGL (FLAREKIT_GL=OFF); rebuild with "
                        "-DFLAREKIT_GL=ON for the GPU paths");
}

Status writeText(const std::string& path, const std::string& text) {
    return writeFileSafely(path, text);
}

std::optional<ToneOperator> namedToneOperator(const std::string& name) {
    for (std::size_t i = 0; i < std::size(kToneOperatorNames); ++i)
        if (kToneOperatorNames[i] == name) return ToneOperator(i);
    return std::nullopt;
}

ToneOperator renderedFrameCurve(const std::string& out, const std::string& tonemap) {
    if (isFloatFormat(outputSampleFormat(out))) return ToneOperator::None;
    return namedToneOperator(tonemap).value_or(ToneOperator::Aces);
}

ToneOperator defaultDisplayCurve(bool hdrInput, const std::string& out, SampleFormat requested) {
    return hdrInput && !isFloatFormat(outputSampleFormat(out, requested)) ? ToneOperator::Filmic
                                                                          : ToneOperator::None;
}

std::vector<std::string> toneChoices(std::initializer_list<const char*> extra) {
    std::vector<std::string> choices(extra.begin(), extra.end());
    for (std::string_view name : kToneOperatorNames) choices.emplace_back(name);
    return choices;
}

}  // namespace flarekit::cli
