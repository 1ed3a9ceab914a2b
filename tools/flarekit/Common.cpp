// SPDX-License-Identifier: Apache-2.0
#include "Common.h"

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
    if (Status s = checkOutputPath(out); !s) return report(s.error());
    auto image = work();
    if (!image) return report(image.error());
    if (Status s = writeImage8(out, *image, encodeSettings()); !s) return report(s.error());
    return kExitOk;
}

Error builtWithoutGl(const std::string& what) {
    return invalidInput(what +
                        ": this flarekit was built without OpenGL (FLAREKIT_GL=OFF); rebuild with "
                        "-DFLAREKIT_GL=ON for the GPU paths");
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
