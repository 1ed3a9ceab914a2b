// SPDX-License-Identifier: Apache-2.0
// Libraries that print on stderr (libpng's "libpng error: ...", Mesa's loader warnings) while
// flarekit reports the same failure in its own one line: their noise held back and replayed
// without the lines that repeat it.
#pragma once

#include <string>
#include <vector>

namespace flarekit {

//! Holds back what libraries print on stderr while it lives; on destruction replays it except
//! the lines starting with one of `dropped` (by default libpng's own "libpng error: ..." lines,
//! which repeat what flarekit reports in its one line). Filters alive at once on several threads
//! share one capture, replayed when the last ends (its first dropped line goes to that one).
class LibraryNoiseFilter {
  public:
    explicit LibraryNoiseFilter(std::vector<std::string> dropped = {"libpng "});
    ~LibraryNoiseFilter();
    LibraryNoiseFilter(const LibraryNoiseFilter&) = delete;
    LibraryNoiseFilter& operator=(const LibraryNoiseFilter&) = delete;
    //! Stops capturing now (replaying what was kept); the first dropped line, trimmed.
    std::string finish();

  private:
    std::vector<std::string> m_dropped;
    std::string m_firstDropped;
    bool m_active = false;
};

}  // namespace flarekit
