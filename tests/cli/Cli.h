// SPDX-License-Identifier: Apache-2.0
// Runs the flarekit binary as a user would and captures exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "TempDir.h"

// A CLI test of an OpenGL path. In a build without OpenGL (FLAREKIT_GL=OFF) it is compiled but
// is no test; NoGlCliTest.cpp checks instead that every GL path refuses with one line.
#if FLAREKIT_HAS_GL
#define FLAREKIT_GL_TEST(suite, name) TEST(suite, name)
#else
#define FLAREKIT_GL_TEST(suite, name) [[maybe_unused]] static void suite##_##name##_needsGl()
#endif

namespace flarekit::test {

struct CliResult {
    int exitCode = -1;
    std::string out, err;
};

inline std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

//! `environment`: NAME=value words set for the run (env(1)), e.g. to hide the Vulkan driver.
inline CliResult runCli(const std::vector<std::string>& args, const std::string& environment = "") {
    static TempDir logs;
    std::string cmd = environment.empty() ? std::string() : "env " + environment + " ";
    cmd.append(quote(FLAREKIT_CLI));
    // append() rather than "literal" + std::string: GCC 12 gives a false -Wrestrict on the latter.
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd.append(" >")
        .append(quote(logs.file("out")))
        .append(" 2>")
        .append(quote(logs.file("err")))
        .append(" </dev/null");
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(logs.file("out"));
    r.err = slurp(logs.file("err"));
    return r;
}

//! Number of lines in a message (a clear error is exactly one).
inline int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

inline const std::string kSunset = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
inline const std::string kSunsetHdr = std::string(FLAREKIT_SAMPLES) + "/sunset-hdr.exr";

}  // namespace flarekit::test
