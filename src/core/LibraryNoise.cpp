// SPDX-License-Identifier: Apache-2.0
#include "core/LibraryNoise.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <mutex>

namespace flarekit {

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

}  // namespace flarekit
