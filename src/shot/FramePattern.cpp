// SPDX-License-Identifier: Apache-2.0
// Frame-number patterns and farm ranges: the file names a shot's frames have on disk.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>

#include "flarekit/Shot.h"

namespace flarekit {

namespace {
//! A frame token found in a name: where it starts, how long it is, its padding.
struct Token {
    std::size_t at = 0, length = 0;
    int padding = 0;
};

//! Every frame token in `text`: runs of '#', "%d" and "%0Nd" / "%Nd".
std::vector<Token> frameTokens(const std::string& text) {
    std::vector<Token> tokens;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '#') {
            std::size_t j = i;
            while (j < text.size() && text[j] == '#') ++j;
            tokens.push_back({i, j - i, int(j - i)});
            i = j;
            continue;
        }
        if (text[i] == '%') {
            std::size_t j = i + 1;
            while (j < text.size() && text[j] >= '0' && text[j] <= '9') ++j;
            if (j < text.size() && text[j] == 'd' && j - i - 1 <= 2) {
                int width = 0;
                std::from_chars(text.data() + i + 1, text.data() + j, width);
                tokens.push_back({i, j + 1 - i, width});
                i = j + 1;
                continue;
            }
        }
        ++i;
    }
    return tokens;
}

std::optional<int> wholeNumber(std::string_view s) {
    int v = 0;
    if (s.empty()) return std::nullopt;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || v < 0) return std::nullopt;
    return v;
}
}  // namespace

std::string FramePattern::path(int frame) const {
    char digits[16];
    std::snprintf(digits, sizeof digits, "%0*d", padding, frame);
    return prefix + digits + suffix;
}

bool isFramePattern(const std::string& text) {
    return !frameTokens(text).empty();
}

Result<FramePattern> parseFramePattern(const std::string& text) {
    const std::vector<Token> tokens = frameTokens(text);
    if (tokens.size() != 1) {
        return invalidInput(text + ": expected one frame-number token (#### or %04d) in a " +
                            "sequence's file name, found " + std::to_string(tokens.size()));
    }
    const Token& t = tokens[0];
    // 9 digits: frame numbers stay within int whatever the padding asks for.
    if (t.padding > 9) return invalidInput(text + ": frame padding over 9 digits");
    return FramePattern{text.substr(0, t.at), text.substr(t.at + t.length), t.padding};
}

std::vector<int> framesOnDisk(const FramePattern& pattern) {
    namespace fs = std::filesystem;
    const fs::path prefixPath(pattern.prefix);
    // "dir/shot." lists dir and matches names starting "shot."; "shot." lists the current one.
    const bool endsInSeparator = !pattern.prefix.empty() && pattern.prefix.back() == '/';
    const fs::path dir = endsInSeparator ? prefixPath : prefixPath.parent_path();
    const std::string stem = endsInSeparator ? "" : prefixPath.filename().string();
    std::vector<int> frames;
    std::error_code ec;
    for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= stem.size() + pattern.suffix.size()) continue;
        if (name.compare(0, stem.size(), stem) != 0) continue;
        if (name.compare(name.size() - pattern.suffix.size(), pattern.suffix.size(),
                         pattern.suffix) != 0)
            continue;
        const std::string_view digits = std::string_view(name).substr(
            stem.size(), name.size() - stem.size() - pattern.suffix.size());
        if (digits.find_first_not_of("0123456789") != std::string_view::npos) continue;
        const auto frame = wholeNumber(digits);
        // The name the pattern gives that frame, exactly: 1001 matches "####" but 01001 does not.
        if (frame && fs::path(pattern.path(*frame)).filename() == name) frames.push_back(*frame);
    }
    std::sort(frames.begin(), frames.end());
    return frames;
}

std::vector<int> FrameRange::frames() const {
    std::vector<int> out;
    for (long long f = first; f <= last; f += step) out.push_back(int(f));
    return out;
}

Result<FrameRange> parseFrameRange(const std::string& text, const std::string& option) {
    auto bad = [&] {
        return invalidInput(option + ": expected A-B[:step] or N (whole frame numbers from 0, " +
                            "A <= B, step >= 1), got '" + text + "'");
    };
    FrameRange r;
    std::string_view s = text;
    if (const auto colon = s.find(':'); colon != std::string_view::npos) {
        const auto step = wholeNumber(s.substr(colon + 1));
        if (!step || *step < 1) return bad();
        r.step = *step;
        s = s.substr(0, colon);
    }
    if (const auto dash = s.find('-'); dash != std::string_view::npos) {
        const auto a = wholeNumber(s.substr(0, dash)), b = wholeNumber(s.substr(dash + 1));
        if (!a || !b || *a > *b) return bad();
        r.first = *a;
        r.last = *b;
    } else {
        const auto n = wholeNumber(s);
        if (!n) return bad();
        r.first = r.last = *n;
    }
    // A million frames (11.5 hours at 24 fps) in one run: the range is listed before any work,
    // so a typo such as 1-1000000000 must not become a list of a billion frames.
    const long long count = (static_cast<long long>(r.last) - r.first) / r.step + 1;
    if (count > kMaxFramesPerRun)
        return invalidInput(option + ": " + text + " is " + std::to_string(count) +
                            " frames; one run takes at most " + std::to_string(kMaxFramesPerRun));
    return r;
}

std::string describeFrames(const std::vector<int>& frames) {
    std::string out;
    for (std::size_t i = 0; i < frames.size();) {
        std::size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        if (!out.empty()) out += ", ";
        out += std::to_string(frames[i]);
        if (j > i) out.append("-").append(std::to_string(frames[j]));
        i = j + 1;
    }
    return out;
}

}  // namespace flarekit
