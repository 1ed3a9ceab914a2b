// SPDX-License-Identifier: Apache-2.0
#include "Common.h"

#include "core/FirstLine.h"
#include "core/Interrupt.h"
#include "core/SafeWrite.h"
#include "flarekit/Limits.h"
#if FLAREKIT_HAS_GL
#include <epoxy/gl.h>
#endif

#include <unistd.h>
#include <algorithm>
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
    // input that echoes megabytes of itself does not reach the terminal. What is cut is the
    // values: the longest words (a 4 KB path, a value without spaces) lose their middle down to
    // 60 characters, first to last, so the reason after them ("File name too long") stays.
    constexpr std::size_t kMax = 1000, kWord = 60;
    std::string_view text = message;
    while (!text.empty() && std::string_view(" \t\r\n").find(text.back()) != std::string_view::npos)
        text.remove_suffix(1);
    std::string line = printable(text);
    while (line.size() > kMax) {
        std::size_t longest = 0, at = 0;
        for (std::size_t i = 0; i < line.size();) {
            const std::size_t end = std::min(line.find(' ', i), line.size());
            if (end - i > longest) longest = end - i, at = i;
            i = end + 1;
        }
        if (longest <= kWord) break;
        // The word's start and its end (a path's file name), the cut never inside a UTF-8
        // sequence.
        std::size_t head = kWord / 2, tail = at + longest - (kWord - head - 3);
        while (head > 0 && (static_cast<unsigned char>(line[at + head]) & 0xC0) == 0x80) --head;
        while ((static_cast<unsigned char>(line[tail]) & 0xC0) == 0x80) ++tail;
        line.replace(at + head, tail - at - head, "...");
    }
    return excerpt(line, kMax);
}

void warn(const std::string& message) {
    std::fprintf(stderr, "flarekit: warning: %s\n", cappedLine(message).c_str());
}

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

EncodeSettings& encodeSettings() {
    static EncodeSettings settings;
    return settings;
}

int runImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work) {
    const auto withSettings = [&]() -> Result<ImageOutput> {
        auto result = work();
        if (result) result->options.encode = encodeSettings();
        return result;
    };
    if (Status s = writeImageJob(out, withSettings); !s) return report(s.error());
    return kExitOk;
}

int runImage8Job(const std::string& out, const std::function<Result<Image8>()>& work) {
    return runWriteJob(
        out, work, [&](const Image8& image) { return writeImage8(out, image, encodeSettings()); });
}

Error builtWithoutGl(const std::string& what) {
    return invalidInput(what +
                        ": this flarekit was built without OpenGL (FLAREKIT_GL=OFF); rebuild with "
                        "-DFLAREKIT_GL=ON for the GPU paths");
}

Status writeText(const std::string& path, const std::string& text) {
    return writeFileSafely(path, text);
}

ToneOperator renderedFrameCurve(const std::string& out, const std::string& tonemap) {
    if (isFloatFormat(outputSampleFormat(out))) return ToneOperator::None;
    return toneOperatorNamed(tonemap).value_or(ToneOperator::Aces);
}

std::vector<std::string> choiceNames(std::span<const std::string_view> names) {
    return {names.begin(), names.end()};
}

int choiceIndex(std::span<const std::string_view> names, std::string_view text) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == text) return int(i);
    return -1;
}

std::vector<std::string> toneChoices(std::initializer_list<const char*> extra) {
    std::vector<std::string> choices(extra.begin(), extra.end());
    for (std::string_view name : kToneOperatorNames) choices.emplace_back(name);
    return choices;
}

}  // namespace flarekit::cli
