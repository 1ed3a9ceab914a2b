// SPDX-License-Identifier: Apache-2.0
// The bugs fixed, each with its input under tests/data/regression/ (README.md there).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "Cli.h"
#include "flarekit/ImageIO.h"
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

// ---------------------------------------------------------------------------------------------
// The bad inputs of tests/data/regression/cases.json: each is run through the CLI and must give
// its exit code and one line naming what was wrong, and write nothing. docs/reliability.md
// lists the same cases (checked below).

namespace {

nlohmann::json regressionCases() {
    return nlohmann::json::parse(slurp(regression("cases.json")));
}

std::string expand(std::string arg, const std::map<std::string, std::string>& places) {
    for (const auto& [key, value] : places) {
        for (std::size_t at; (at = arg.find(key)) != std::string::npos;)
            arg.replace(at, key.size(), value);
    }
    return arg;
}

//! A 3840x2160 dark frame, made once for the cases that need a 4K image.
const std::string& workDirectory() {
    static TempDir work;
    static const bool made = [] {
        flarekit::Image image(3840, 2160);
        image.fill({0.05f, 0.05f, 0.05f, 1.f});
        return flarekit::writeImage(work.file("4k.png"), image).ok();
    }();
    EXPECT_TRUE(made);
    return work.path().native();
}

//! The table docs/reliability.md must hold, one row per case.
std::string casesTable(const nlohmann::json& cases) {
    std::string table = "| case | kind | before | now |\n|---|---|---|---|\n";
    for (const auto& c : cases) {
        table += "| `" + c["name"].get<std::string>() + "` | " + c["kind"].get<std::string>() +
                 " | " + c["bug"].get<std::string>() + " | exit " +
                 std::to_string(c["exit"].get<int>()) + ": `..." + c["stderr"].get<std::string>() +
                 "...` |\n";
    }
    return table;
}

}  // namespace

TEST(Regression, EveryBadInputCaseGivesOneLineAndWritesNothing) {
    const nlohmann::json cases = regressionCases();
    ASSERT_GE(cases.size(), 10u);
    for (const auto& c : cases) {
        const std::string name = c["name"];
        SCOPED_TRACE(name);
        TempDir out;
        const std::map<std::string, std::string> places = {
            {"{samples}", FLAREKIT_SAMPLES},
            {"{data}", FLAREKIT_REGRESSION_DATA},
            {"{out}", out.path().native()},
            {"{work}", c.contains("setup") ? workDirectory() : std::string("/nonexistent")}};
        std::vector<std::string> args;
        for (const auto& a : c["args"]) args.push_back(expand(a.get<std::string>(), places));
        const CliResult r = runCli(args);
        std::string expected = c["stderr"];
#if !FLAREKIT_HAS_GL
        if (c["gl"].get<bool>()) expected = "built without OpenGL";
#endif
        EXPECT_EQ(r.exitCode, c["exit"].get<int>()) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_LT(r.err.size(), 1000u) << r.err.substr(0, 2000);
        EXPECT_EQ(out.entries(), 0u) << "a failed run left files behind";
    }
}

TEST(Regression, ReliabilityPageListsEveryCase) {
    const std::string page = std::string(FLAREKIT_DOCS) + "/reliability.md";
    const std::string begin = "<!-- regression cases: tests/data/regression/cases.json -->\n",
                      end = "<!-- end regression cases -->";
    std::string text = slurp(page);
    const auto b = text.find(begin), e = text.find(end);
    ASSERT_NE(b, std::string::npos) << page;
    ASSERT_NE(e, std::string::npos) << page;
    const std::string table = casesTable(regressionCases());
    if (std::getenv("FLAREKIT_UPDATE_DOCS")) {
        text.replace(b + begin.size(), e - b - begin.size(), table);
        std::ofstream(page) << text;
    }
    EXPECT_EQ(text.substr(b + begin.size(), e - b - begin.size()), table)
        << "run FLAREKIT_UPDATE_DOCS=1 ctest --test-dir build -R ReliabilityPage";
}
