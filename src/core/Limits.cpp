// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Limits.h"

#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace flarekit {

namespace {
std::mutex g_mutex;
ResourceLimits g_limits;
}  // namespace

ResourceLimits resourceLimits() {
    std::lock_guard lock(g_mutex);
    return g_limits;
}

void setResourceLimits(const ResourceLimits& limits) {
    std::lock_guard lock(g_mutex);
    g_limits = limits;
}

std::string formatBytes(double bytes) {
    char text[64];
    if (bytes < 1024) {
        std::snprintf(text, sizeof text, "%.0f bytes", bytes);
    } else if (bytes < 1024.0 * 1024) {
        std::snprintf(text, sizeof text, "%.3g KiB", bytes / 1024);
    } else if (bytes < 1024.0 * 1024 * 1024) {
        std::snprintf(text, sizeof text, "%.3g MiB", bytes / (1024.0 * 1024));
    } else {
        std::snprintf(text, sizeof text, "%.3g GiB", bytes / (1024.0 * 1024 * 1024));
    }
    return text;
}

Status checkMemory(const std::string& what, double bytes, const std::string& detail) {
    const double budget = double(resourceLimits().maxMemoryBytes);
    if (bytes <= budget) return Ok{};
    return invalidInput(what + ": needs an estimated " + formatBytes(bytes) +
                        (detail.empty() ? "" : " (" + detail + ")") +
                        ", over the memory budget of " + formatBytes(budget) +
                        " (raise it with --max-memory or FLAREKIT_MAX_MEMORY)");
}

std::optional<std::uint64_t> parseByteSize(std::string_view text) {
    double value = 0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || !std::isfinite(value) || value < 0) return std::nullopt;
    std::string unit(ptr, end);
    for (char& c : unit) c = char(std::tolower(static_cast<unsigned char>(c)));
    double scale = 1;
    if (unit.empty() || unit == "b") {
        scale = 1;
    } else if (unit == "k" || unit == "kb" || unit == "kib") {
        scale = 1024.0;
    } else if (unit == "m" || unit == "mb" || unit == "mib") {
        scale = 1024.0 * 1024;
    } else if (unit == "g" || unit == "gb" || unit == "gib") {
        scale = 1024.0 * 1024 * 1024;
    } else if (unit == "t" || unit == "tb" || unit == "tib") {
        scale = 1024.0 * 1024 * 1024 * 1024;
    } else {
        return std::nullopt;
    }
    const double bytes = value * scale;
    if (bytes < 1 || bytes > 9.0e18) return std::nullopt;
    return std::uint64_t(bytes);
}

}  // namespace flarekit
