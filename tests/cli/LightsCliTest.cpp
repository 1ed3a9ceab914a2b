// SPDX-License-Identifier: Apache-2.0
// `flarekit lights` and the many-light Scene JSON through the CLI: every light measured by the
// engine API (and by `visibility --method compute`, the same pass) against the ray caster, the
// "lights" array of `visibility --json`, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "Cli.h"

using namespace flarekit::test;

namespace {
const std::string kCity = std::string(FLAREKIT_SAMPLES) + "/scenes/city-lamps.json";

//! Light i's radius on screen in pixels.
double radiusPx(const nlohmann::json& scene, std::size_t i) {
    const auto& eye = scene["camera"]["position"];
    const double focal = double(scene["image"]["height"]) / 2 /
                         std::tan(double(scene["camera"]["fov_y_deg"]) * M_PI / 360);
    const auto& l = scene["lights"][i];
    if (l["type"] != "point") return focal * double(l["angular_radius_deg"]) * M_PI / 180;
    const auto& p = l["position"];
    return focal * double(l["radius"]) /
           std::hypot(double(p[0]) - double(eye[0]), double(p[1]) - double(eye[1]),
                      double(p[2]) - double(eye[2]));
}
}  // namespace

TEST(CliVisibility, JsonListsEveryLightInSceneOrder) {
    const CliResult r = runCli({"visibility", kCity, "--samples", "16", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["lights"].size(), 255u);
    EXPECT_EQ(j["lights"][0]["coverage"], j["coverage"]);  // the top level is the first light
    const CliResult one = runCli(
        {"visibility", std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json", "--json"});
    ASSERT_EQ(one.exitCode, 0);
    EXPECT_NE(one.out.find("\"lights\": [{\"coverage\": "), std::string::npos) << one.out;
}

FLAREKIT_GL_TEST(CliLights, EveryLightMatchesTheRayCasterAndTheImageHasTheirFlares) {
    TempDir dir;
    const CliResult r =
        runCli({"lights", kCity, "-o", dir.file("city.png"), "--msaa", "4", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto engine = nlohmann::json::parse(r.out);
    EXPECT_EQ(engine["method"], "compute");
    ASSERT_EQ(engine["lights_coverage"].size(), 255u);
    EXPECT_TRUE(std::filesystem::file_size(dir.file("city.png")) > 10000);

    const CliResult compute =
        runCli({"visibility", kCity, "--method", "compute", "--msaa", "4", "--json"});
    ASSERT_EQ(compute.exitCode, 0) << compute.err;
    const auto sameApi = nlohmann::json::parse(compute.out)["lights"];
    const CliResult rays = runCli({"visibility", kCity, "--samples", "64", "--json"});
    ASSERT_EQ(rays.exitCode, 0) << rays.err;
    const auto truth = nlohmann::json::parse(rays.out)["lights"];
    const auto scene = nlohmann::json::parse(slurp(kCity));
    int compared = 0, small = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        // The same pass through both subcommands.
        EXPECT_EQ(sameApi[i]["coverage"], engine["lights_coverage"][i]["coverage"]) << i;
        // Every in-frame light, sub-pixel ones included: those under 1,024 depth samples are
        // measured from sun maps the scene's occluder callback draws.
        if (double(truth[i]["in_frame"]) < 1) continue;
        EXPECT_NEAR(double(engine["lights_coverage"][i]["coverage"]), double(truth[i]["coverage"]),
                    0.02)
            << "light " << i << ", " << radiusPx(scene, i) << " px";
        ++compared;
        small += radiusPx(scene, i) < 2 ? 1 : 0;
    }
    EXPECT_GE(compared, 40);
    EXPECT_GE(small, 10);
}

FLAREKIT_GL_TEST(CliLights, TheVulkanBackendMeasuresAndDrawsAsTheGlBackendDoes) {
    // The city through lavapipe with the validation layer on (any message fails the run), its
    // depth drawn again by a Vulkan depth pass and its small lamps' sun maps by the Vulkan
    // occluder callback: the GL backend's coverage, within what two rasterizers differ by.
    TempDir dir;
    const CliResult vk = runCli(
        {"lights", kCity, "-o", dir.file("vk.png"), "--msaa", "4", "--backend", "vulkan", "--json"},
        "FLAREKIT_VULKAN_VALIDATION=1");
    ASSERT_EQ(vk.exitCode, 0) << vk.err;
    const CliResult gl =
        runCli({"lights", kCity, "-o", dir.file("gl.png"), "--msaa", "4", "--json"});
    ASSERT_EQ(gl.exitCode, 0) << gl.err;
    const auto a = nlohmann::json::parse(vk.out)["lights_coverage"];
    const auto b = nlohmann::json::parse(gl.out)["lights_coverage"];
    ASSERT_EQ(a.size(), b.size());
    double worst = 0, sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(double(a[i]["coverage"]) - double(b[i]["coverage"]));
        worst = std::max(worst, d), sum += d;
        EXPECT_EQ(a[i]["in_frame"], b[i]["in_frame"]) << i;
    }
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(sum / double(a.size()), 0.002);
    const CliResult visibility = runCli({"visibility", kCity, "--method", "compute", "--backend",
                                         "vulkan", "--msaa", "4", "--json"});
    ASSERT_EQ(visibility.exitCode, 0) << visibility.err;
    const auto v = nlohmann::json::parse(visibility.out)["lights"];
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(v[i]["coverage"], a[i]["coverage"]) << i;
    EXPECT_GT(std::filesystem::file_size(dir.file("vk.png")), 10000u);

    // Without a Vulkan driver: one line, exit 2, nothing written.
    const CliResult none =
        runCli({"lights", kCity, "-o", dir.file("none.png"), "--backend", "vulkan"},
               "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json");
    EXPECT_EQ(none.exitCode, 2) << none.err;
    EXPECT_EQ(lineCount(none.err), 1) << none.err;
    EXPECT_NE(none.err.find("--backend vulkan"), std::string::npos) << none.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("none.png")));
    const CliResult mask = runCli({"lights", kCity, "-o", dir.file("mask.png"), "--backend",
                                   "vulkan", "--method", "texture-mask"});
    EXPECT_EQ(mask.exitCode, 2);
    EXPECT_NE(mask.err.find("expected --method compute"), std::string::npos) << mask.err;
    const CliResult rays = runCli({"visibility", kCity, "--backend", "vulkan"});
    EXPECT_EQ(rays.exitCode, 2);
    EXPECT_EQ(lineCount(rays.err), 1) << rays.err;
}

FLAREKIT_GL_TEST(CliLights, BadInputExitsTwoWithOneLineAndWritesNothing) {
    TempDir dir;
    auto scene = nlohmann::json::parse(slurp(kCity));
    scene["lights"][3]["preset"] = "no-such-preset";
    scene["lights"][1]["preset"] = "";  // draws no flare: the bad light is still named by its index
    const std::string badPreset = dir.file("bad-preset.json");
    std::ofstream(badPreset) << scene.dump();
    const std::string out = dir.file("out.png");
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    for (const Case& c : std::vector<Case>{
             {{"lights", badPreset, "-o", out}, badPreset + ": lights[3].preset: "},
             {{"lights", dir.file("missing.json"), "-o", out}, "missing.json"},
             {{"lights", kCity, "-o", out, "--method", "pbo"}, "--method"},
             {{"lights", kCity, "-o", out, "--samples", "0"}, "--samples"},
             {{"lights", kCity, "-o", out, "--tile-below", "-1"}, "--tile-below"},
             {{"lights", kCity, "-o", kCity + std::string("/x.png")},
              "city-lamps.json' is not a directory"},
         }) {
        const CliResult r = runCli(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args[1] << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

FLAREKIT_GL_TEST(CliVisibility, TextureMaskMeasuresEveryLightOfAManyLightSceneEvenOffScreen) {
    // A sun map per light through the engine API's occluder callback: unlike the depth pass it
    // needs no light to be in frame or large on screen.
    const CliResult mask = runCli({"visibility", kCity, "--method", "texture-mask", "--json"});
    ASSERT_EQ(mask.exitCode, 0) << mask.err;
    const CliResult rays = runCli({"visibility", kCity, "--samples", "64", "--json"});
    ASSERT_EQ(rays.exitCode, 0) << rays.err;
    const auto measured = nlohmann::json::parse(mask.out)["lights"];
    const auto truth = nlohmann::json::parse(rays.out)["lights"];
    ASSERT_EQ(measured.size(), truth.size());
    int offScreenSeen = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        EXPECT_NEAR(double(measured[i]["coverage"]), double(truth[i]["coverage"]), 0.02) << i;
        offScreenSeen += double(truth[i]["in_frame"]) == 0 && double(truth[i]["coverage"]) > 0.5;
    }
    EXPECT_GE(offScreenSeen, 5);
}

FLAREKIT_GL_TEST(CliVisibility, EveryGpuMethodMeasuresEveryLightPointLightsIncluded) {
    // A lamp before a wall, one behind it, a big sphere light partly behind a post and a
    // directional light past the wall's edge but behind the post: each one-light method of
    // the seeds measures each light as its sun (a point light's disc, seen where the depth
    // reaches its near side); compute and texture-mask measure all at once.
    TempDir dir;
    const std::string scene = dir.file("lights.json");
    std::ofstream(scene) << R"({"image": {"width": 320, "height": 180},
        "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]},
        "lights": [{"type": "point", "position": [0.5, 0.5, -10], "radius": 0.3},
                   {"type": "point", "position": [0.5, 0.5, -30], "radius": 0.3},
                   {"type": "point", "position": [4.6, 0.0, -15], "radius": 0.6},
                   {"type": "directional", "direction": [0.3, 0.15, -1], "angular_radius_deg": 1}],
        "objects": [{"type": "box", "min": [-4, -4, -21], "max": [4, 4, -20]},
                    {"type": "box", "min": [4.0, -3, -12.05], "max": [4.5, 3, -12]}]})";
    const CliResult rays = runCli({"visibility", scene, "--json"});
    ASSERT_EQ(rays.exitCode, 0) << rays.err;
    const auto truth = nlohmann::json::parse(rays.out)["lights"];
    ASSERT_EQ(truth.size(), 4u);
    EXPECT_EQ(double(truth[0]["coverage"]), 1.0);
    EXPECT_EQ(double(truth[1]["coverage"]), 0.0);
    EXPECT_GT(double(truth[2]["coverage"]), 0.5);
    EXPECT_LT(double(truth[2]["coverage"]), 0.95);
    for (const char* method : {"readback", "pbo", "query", "texture-mask", "texture-mask-screen",
                               "burnout", "compute"}) {
        const CliResult r =
            runCli({"visibility", scene, "--method", method, "--msaa", "4", "--json"});
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.err;
        const auto got = nlohmann::json::parse(r.out)["lights"];
        ASSERT_EQ(got.size(), 4u) << method;
        for (std::size_t i = 0; i < 4; ++i) {
            // The seeds' methods' own bound at 4x MSAA (docs/occlusion.md: 0.012-0.020).
            EXPECT_NEAR(double(got[i]["coverage"]), double(truth[i]["coverage"]), 0.025)
                << method << ", light " << i;
        }
    }
}
