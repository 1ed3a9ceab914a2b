// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Video.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "core/Interrupt.h"

namespace flarekit {

std::string findFfmpeg() {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/ffmpeg";
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return "";
}

namespace {
constexpr int kInterruptedRun = -2;

//! Runs argv with stdout and stderr appended to logPath; returns the exit status (-1: no start,
//! kInterruptedRun: stopped for SIGINT/SIGTERM).
int runLogged(const std::vector<std::string>& args, const std::string& logPath) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND,
                                     0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    TrackedChild tracked(pid);
    // Polled rather than a blocking wait, so that an interrupt stops ffmpeg (a SIGTERM sent to
    // flarekit alone would not reach it) and reaps it before flarekit exits.
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) return -1;
        if (interrupted()) {
            kill(pid, SIGTERM);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            return kInterruptedRun;
        }
        usleep(20 * 1000);  // 20 ms: no visible delay, negligible CPU next to ffmpeg's
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

Status encodeVideo(const std::string& ffmpeg, const std::string& pattern, double fps,
                   const std::string& output, const std::string& logPath) {
    const std::string temp = output + ".partial.mp4";
    TrackedTempPath trackedTemp(temp);  // removed by a second SIGINT/SIGTERM too
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    // CRF 18: visually lossless for H.264; yuv420p so every player opens it; faststart so it
    // streams. Frame sizes must be even for 4:2:0, so odd sizes are padded by one pixel.
    const std::vector<std::string> common = {ffmpeg,
                                             "-y",
                                             "-nostdin",
                                             "-loglevel",
                                             "error",
                                             "-framerate",
                                             rate,
                                             "-i",
                                             pattern,
                                             "-vf",
                                             "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                             "-pix_fmt",
                                             "yuv420p",
                                             "-movflags",
                                             "+faststart"};
    std::vector<std::string> h264 = common, mpeg4 = common;
    for (const char* a : {"-c:v", "libx264", "-preset", "medium", "-crf", "18"})
        h264.emplace_back(a);
    for (const char* a : {"-c:v", "mpeg4", "-q:v", "3"}) mpeg4.emplace_back(a);
    h264.push_back(temp);
    mpeg4.push_back(temp);
    int rc = runLogged(h264, logPath);
    if (rc != 0 && rc != kInterruptedRun) rc = runLogged(mpeg4, logPath);
    std::error_code ec;
    if (rc == kInterruptedRun) {
        std::filesystem::remove(temp, ec);
        return interruptedError("the frames are complete; ffmpeg was stopped and no video written");
    }
    if (rc != 0) {
        std::filesystem::remove(temp, ec);
        return ioError(output + ": ffmpeg failed (exit " + std::to_string(rc) + "); see " +
                       logPath);
    }
    std::filesystem::rename(temp, output, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return ioError(output + ": cannot rename the encoded video: " + ec.message());
    }
    return Ok{};
}

}  // namespace flarekit
