// The bugs fixed, each with its input under tests/data/regression/ (README.md there).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "Cli.h"
#include "flarekit/PostFx.h"

using namespace flarekit::test;

namespace {
std::string regression(const std::string& name) {
    return std::string(FLAREKIT_REGRESSION_DATA) + "/" + name;
}
}  // namespace

TEST(Regression, SeedRangeIsPrintedInFull) {
    TempDir dir;
    const CliResult r =
        runCli({"postfx", std::string(FLAREKIT_SAMPLES) + "/sunset.png", "-o", dir.file("o.png"),
                "--preset", regression("postfx-seed-past-range.json")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("dirt.seed: expected an integer in [0, 2147483647], got 3000000000"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
}

TEST(Regression, PspDemoProgressEndsEveryLineWhenNotATerminal) {
    TempDir dir;
    const CliResult r =
        runCli({"psp", "demo", "-o", dir.file("demo"), "--frames", "3"});  // stderr is a pipe
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream lines(r.err);
    int progressLines = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("psp demo:", 0) != 0) continue;
        ++progressLines;
        EXPECT_EQ(std::count(line.begin(), line.end(), '/'), 1)
            << "two progress reports on one line: " << line;
    }
    EXPECT_EQ(progressLines, 3) << r.err;
    EXPECT_TRUE(r.err.empty() || r.err.back() == '\n') << r.err;
}

TEST(Regression, StarburstWidthRangeIsTheSameForJsonAndCode) {
    auto fromJson = flarekit::loadPostFxPreset(regression("starburst-width-in-code.json"));
    ASSERT_FALSE(fromJson.ok());
    EXPECT_NE(
        fromJson.error().message.find("starburst.width: expected a number in [0.01, 1], got 0.005"),
        std::string::npos);
    flarekit::PostFxParams code;
    code.starburst.intensity = 0.5f;
    code.starburst.width = 0.005f;
    auto run = flarekit::postFxCpu(flarekit::Image(16, 16), code);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().message,
              "postfx: starburst.width: expected a number in [0.01, 1], got 0.005");
}
