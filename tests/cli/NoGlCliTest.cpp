// SPDX-License-Identifier: Apache-2.0
// A build without OpenGL (FLAREKIT_GL=OFF): every GL path of the CLI exits 2 with one line that
// says so, and writes nothing; the CPU paths of the same subcommands still work.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "Cli.h"

using namespace flarekit::test;

#if !FLAREKIT_HAS_GL
TEST(CliWithoutGl, GlPathsRefuseWithOneLineAndWriteNothing) {
    TempDir dir;
    const std::string scene = std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json";
    const std::string sunset = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
    const std::string city = std::string(FLAREKIT_SAMPLES) + "/scenes/city-lamps.json";
    for (const std::vector<std::string>& args : {
             std::vector<std::string>{"render", scene, "-o", dir.file("r.png")},
             {"demo", "-o", dir.file("drive"), "--frames", "2"},
             {"visibility", scene, "--method", "compute"},
             {"postfx", sunset, "-o", dir.file("p.png"), "--backend", "gl"},
             {"lights", city, "-o", dir.file("l.png")},
             {"visibility", city, "--method", "compute"},
         }) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
        EXPECT_NE(r.err.find("built without OpenGL"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
    // The same subcommands' CPU paths.
    EXPECT_EQ(runCli({"visibility", scene, "--method", "raycast", "--json"}).exitCode, 0);
    EXPECT_EQ(runCli({"visibility", city, "--method", "raycast", "--samples", "8"}).exitCode, 0);
    EXPECT_EQ(runCli({"postfx", sunset, "-o", dir.file("p.png")}).exitCode, 0);
}
#endif
