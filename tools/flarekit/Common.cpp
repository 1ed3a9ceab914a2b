#include "Common.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace flarekit::cli {

int report(const Error& error) {
    std::fprintf(stderr, "flarekit: %s\n", error.message.c_str());
    return error.code == ErrorCode::Internal ? kExitInternal : kExitBadInput;
}

void warn(const std::string& message) { std::fprintf(stderr, "flarekit: warning: %s\n", message.c_str()); }

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

}  // namespace flarekit::cli
