// SPDX-License-Identifier: Apache-2.0
#include "Progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace flarekit::cli {

std::string formatDuration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

Progress::Progress(std::string label, int total)
    : m_label(std::move(label)),
      m_total(total > 0 ? total : 1),
      m_tty(isatty(fileno(stderr)) == 1),
      m_start(std::chrono::steady_clock::now()) {}

void Progress::update(int done) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const double rate = elapsed > 0 ? done / elapsed : 0;
    const double eta = rate > 0 ? (m_total - done) / rate : 0;
    if (m_tty) {
        m_drawn = true;
        constexpr int kWidth = 30;
        const int filled = done * kWidth / m_total;
        std::string bar(std::size_t(filled), '#');
        bar.append(std::size_t(kWidth - filled), '.');
        std::fprintf(stderr, "\r%s [%s] %d/%d  %.1f/s  ETA %s ", m_label.c_str(), bar.c_str(), done,
                     m_total, rate, formatDuration(eta).c_str());
        std::fflush(stderr);
        return;
    }
    const int decile = done * 10 / m_total;
    if (decile == m_lastDecile) return;
    m_lastDecile = decile;
    std::fprintf(stderr, "%s: %d/%d (%d%%), %s elapsed, ETA %s\n", m_label.c_str(), done, m_total,
                 decile * 10, formatDuration(elapsed).c_str(), formatDuration(eta).c_str());
}

void Progress::finish() {
    if (m_tty && m_drawn) std::fprintf(stderr, "\n");
    m_drawn = false;
}

}  // namespace flarekit::cli
