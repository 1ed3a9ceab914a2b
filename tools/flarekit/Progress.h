// SPDX-License-Identifier: Apache-2.0
// Progress of a long job on stderr: a redrawn bar with rate and ETA on a terminal, one plain
// line per 10% otherwise (logs and CI keep readable output).
#pragma once

#include <chrono>
#include <string>

namespace flarekit::cli {

class Progress {
  public:
    Progress(std::string label, int total);
    void update(int done);  //!< done items so far (monotonic)
    void setTotal(int total) { m_total = total > 0 ? total : 1; }
    void finish();  //!< ends the bar's line

  private:
    std::string m_label;
    int m_total;
    int m_lastDecile = -1;
    bool m_tty;
    bool m_drawn = false;  //!< a bar is on the terminal's line
    std::chrono::steady_clock::time_point m_start;
};

//! "1:05" style duration.
std::string formatDuration(double seconds);

}  // namespace flarekit::cli
