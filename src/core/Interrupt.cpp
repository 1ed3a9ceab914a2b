// SPDX-License-Identifier: Apache-2.0
#include "core/Interrupt.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace flarekit {

namespace {

std::atomic<int> g_signal{0};

// Fixed slots, so that the handler touches no heap and no lock (only async-signal-safe calls:
// unlink, kill, waitpid, _exit). 64 temporary files and 8 children cover every command: the demo
// has at most 3 frames in flight and one ffmpeg.
constexpr int kMaxTrackedPaths = 64, kMaxPathBytes = 4096, kMaxTrackedChildren = 8;
char g_paths[kMaxTrackedPaths][kMaxPathBytes];
enum SlotState : int { kFree, kFilling, kReady };  // the handler unlinks kReady slots only
std::atomic<int> g_pathState[kMaxTrackedPaths];
std::atomic<pid_t> g_children[kMaxTrackedChildren];

void onSignal(int sig) {
    int expected = 0;
    if (g_signal.compare_exchange_strong(expected, sig)) return;  // first: stop at a safe point
    // Second signal: the user does not want to wait. Clean up and leave now.
    for (int i = 0; i < kMaxTrackedPaths; ++i)
        if (g_pathState[i].load() == kReady) ::unlink(g_paths[i]);
    for (auto& child : g_children) {
        const pid_t pid = child.load();
        if (pid > 0) ::kill(pid, SIGKILL), ::waitpid(pid, nullptr, 0);
    }
    static const char kLine[] =
        "flarekit: interrupted twice: stopped at once; temporary files "
        "removed, nothing partial left\n";
    (void)!::write(STDERR_FILENO, kLine, sizeof kLine - 1);
    ::_exit(128 + g_signal.load());
}

}  // namespace

void installInterruptHandlers() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // library reads and writes carry on; commands poll the flag
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() {
    return g_signal.load(std::memory_order_relaxed) != 0;
}

int interruptSignal() {
    return g_signal.load();
}

std::string interruptSignalName() {
    const int sig = g_signal.load();
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "signal " + std::to_string(sig);
}

Error interruptedError(const std::string& what) {
    return {ErrorCode::Interrupted, "interrupted by " + interruptSignalName() + ": " + what};
}

TrackedTempPath::TrackedTempPath(const std::string& path) {
    if (path.size() >= std::size_t(kMaxPathBytes)) return;
    for (int i = 0; i < kMaxTrackedPaths; ++i) {
        int expected = kFree;
        if (g_pathState[i].compare_exchange_strong(expected, kFilling)) {
            std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
            g_pathState[i].store(kReady);
            m_slot = i;
            return;
        }
    }
}

TrackedTempPath::~TrackedTempPath() {
    if (m_slot >= 0) g_pathState[m_slot].store(kFree);
}

TrackedChild::TrackedChild(pid_t pid) {
    for (int i = 0; i < kMaxTrackedChildren; ++i) {
        pid_t expected = 0;
        if (g_children[i].compare_exchange_strong(expected, pid)) {
            m_slot = i;
            return;
        }
    }
}

TrackedChild::~TrackedChild() {
    if (m_slot >= 0) g_children[m_slot].store(0);
}

}  // namespace flarekit
