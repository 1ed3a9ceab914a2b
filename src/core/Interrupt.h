// SPDX-License-Identifier: Apache-2.0
// SIGINT and SIGTERM: the first one asks every command to stop at its next safe point (between
// frames, before a file is committed); the second one stops at once. Either way temporary files
// are removed and child processes are killed and reaped, so only complete outputs remain.
#pragma once

#include <sys/types.h>

#include <string>

#include "flarekit/Result.h"

namespace flarekit {

//! Installs the handlers (idempotent). Until then interrupted() is always false.
void installInterruptHandlers();
//! Whether SIGINT or SIGTERM has arrived; safe to call from any thread.
bool interrupted();
//! The signal that arrived (SIGINT, SIGTERM), 0 if none.
int interruptSignal();
//! "SIGINT" / "SIGTERM".
std::string interruptSignalName();
//! The error a command returns when it stops for an interrupt; `what` says what was finished.
Error interruptedError(const std::string& what);

//! A path that the second signal's handler unlinks while it is registered (a temporary file
//! being written). At most kMaxTrackedPaths at a time; more are simply not tracked.
class TrackedTempPath {
  public:
    explicit TrackedTempPath(const std::string& path);
    ~TrackedTempPath();
    TrackedTempPath(const TrackedTempPath&) = delete;
    TrackedTempPath& operator=(const TrackedTempPath&) = delete;

  private:
    int m_slot = -1;
};

//! A child process that the second signal's handler kills (SIGKILL) and reaps while registered.
class TrackedChild {
  public:
    explicit TrackedChild(pid_t pid);
    ~TrackedChild();
    TrackedChild(const TrackedChild&) = delete;
    TrackedChild& operator=(const TrackedChild&) = delete;

  private:
    int m_slot = -1;
};

}  // namespace flarekit
