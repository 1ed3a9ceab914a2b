// SPDX-License-Identifier: Apache-2.0
// The installed package as an outside project uses it: `cmake --install` into a fresh prefix,
// examples/embed-gl configured with find_package(flarekit 0.2) against that prefix alone,
// built and run (its own EGL context, reversed-Z MSAA depth, a sun and 254 street lamps),
// its coverage checked against `flarekit visibility --method raycast`; and a C program built
// with pkg-config.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "TempDir.h"

using flarekit::test::TempDir;

namespace {

int run(const std::string& command, const std::string& log) {
    const int status = std::system((command + " >" + log + " 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Lamps whose sphere is under 2 px in radius on screen are below what a depth buffer resolves
// (a 1-px light is 4 samples of 4x MSAA); the comparison keeps those at 2 px and more.
constexpr double kMinRadiusPx = 2.0;
//! 0.02, or for small lights what 4x MSAA depth can resolve: its samples sit a quarter pixel
//! apart, so an edge is placed to within 1/8 px, which moves up to 2R x 1/8 px^2 of a light
//! of radius R px (area pi R^2): 0.08 / R.
double depthTolerance(double radiusPx) {
    return std::max(0.02, 0.08 / radiusPx);
}

//! A private X server for the window test: Xvfb on a free display number, listening on its
//! local socket only (-nolisten tcp), stopped when the test ends.
class Xvfb {
  public:
    Xvfb() {
        for (int n = 90; n < 190 && m_pid == 0; ++n) {
            const std::string socket = "/tmp/.X11-unix/X" + std::to_string(n);
            if (std::filesystem::exists(socket) ||
                std::filesystem::exists("/tmp/.X" + std::to_string(n) + "-lock"))
                continue;
            const std::string display = ":" + std::to_string(n);
            const char* argv[] = {"Xvfb", display.c_str(), "-nolisten", "tcp", "-screen",
                                  "0",    "1280x800x24",   nullptr};
            if (posix_spawnp(&m_pid, "Xvfb", nullptr, nullptr, const_cast<char**>(argv), environ) !=
                0) {
                m_pid = 0;
                return;
            }
            for (int wait = 0; wait < 100 && !std::filesystem::exists(socket); ++wait)
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            m_display = display;
        }
    }
    ~Xvfb() {
        if (m_pid == 0) return;
        kill(m_pid, SIGTERM);
        waitpid(m_pid, nullptr, 0);
    }
    const std::string& display() const { return m_display; }

  private:
    pid_t m_pid = 0;
    std::string m_display;
};

}  // namespace

TEST(Package, AVulkanApplicationBuildsAgainstThePackageAndMatchesTheRayCasterUnderValidation) {
    // examples/embed-vk: its own instance, device, 4x MSAA reversed-Z depth image and frames in
    // flight; flarekit records into its command buffers, with the validation layer on.
    TempDir dir;
    const std::string prefix = dir.file("prefix"), build = dir.file("embed-vk"),
                      log = dir.file("log");
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --install " + FLAREKIT_BUILD_DIR + " --prefix " +
                      prefix,
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " -S " + FLAREKIT_VK_EXAMPLE_DIR + " -B " + build +
                      " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + prefix,
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --build " + build, log), 0) << slurp(log);
    const std::string scene = dir.file("city.json"), coverage = dir.file("coverage.json"),
                      rays = dir.file("rays.json"), frame = dir.file("frame.ppm");
    ASSERT_EQ(run(build + "/embed-vk --validate --frames 3 --out " + frame + " --scene-json " +
                      scene + " --coverage-json " + coverage,
                  log),
              0)
        << slurp(log);
    EXPECT_NE(slurp(log).find("255 lights"), std::string::npos) << slurp(log);
    EXPECT_EQ(slurp(log).find("validation"), std::string::npos) << slurp(log);
    // "P6\n1280 720\n255\n" and the RGB bytes.
    EXPECT_EQ(std::filesystem::file_size(frame), std::size_t(16 + 1280 * 720 * 3));
    ASSERT_EQ(run(std::string(FLAREKIT_CLI) + " visibility " + scene +
                      " --method raycast --samples 64 --json",
                  rays),
              0)
        << slurp(rays);
    const auto sceneJson = nlohmann::json::parse(slurp(scene));
    const auto engine = nlohmann::json::parse(slurp(coverage))["coverage"];
    const auto truth = nlohmann::json::parse(slurp(rays))["lights"];
    ASSERT_EQ(engine.size(), truth.size());
    const auto& eye = sceneJson["camera"]["position"];
    const double focalPx = double(sceneJson["image"]["height"]) / 2 /
                           std::tan(double(sceneJson["camera"]["fov_y_deg"]) * M_PI / 360);
    int compared = 0, hidden = 0;
    for (std::size_t i = 1; i < engine.size(); ++i) {  // the lamps
        const auto& p = sceneJson["lights"][i]["position"];
        const double d = std::hypot(double(p[0]) - double(eye[0]), double(p[1]) - double(eye[1]),
                                    double(p[2]) - double(eye[2]));
        const double radiusPx = focalPx * double(sceneJson["lights"][i]["radius"]) / d;
        if (double(truth[i]["in_frame"]) < 1 || radiusPx < kMinRadiusPx) continue;
        const double t = truth[i]["coverage"];
        EXPECT_NEAR(double(engine[i]), t, depthTolerance(radiusPx))
            << "light " << i << ", " << radiusPx << " px";
        ++compared;
        hidden += t == 0 ? 1 : 0;
    }
    EXPECT_GE(compared, 40);
    EXPECT_GE(hidden, 10);

    // With a display it opens a window (GLFW, a swapchain it presents to) and measures the same.
    const Xvfb x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    const std::string windowed = dir.file("windowed.json");
    ASSERT_EQ(
        run("DISPLAY=" + x.display() + " " + build + "/embed-vk --validate --frames 3 --out " +
                dir.file("window.ppm") + " --coverage-json " + windowed,
            log),
        0)
        << slurp(log);
    EXPECT_NE(slurp(log).find("a 1280x720 window (GLFW"), std::string::npos) << slurp(log);
    EXPECT_EQ(slurp(log).find("validation"), std::string::npos) << slurp(log);
    const auto inWindow = nlohmann::json::parse(slurp(windowed))["coverage"];
    ASSERT_EQ(inWindow.size(), engine.size());
    for (std::size_t i = 0; i < engine.size(); ++i)
        EXPECT_NEAR(double(inWindow[i]), double(engine[i]), 1e-4) << "light " << i;
    EXPECT_EQ(slurp(dir.file("window.ppm")), slurp(frame));  // the same frames, off screen or not
}

TEST(Package, AnOutsideProjectBuildsAgainstTheInstalledPackageAndMatchesTheRayCaster) {
    TempDir dir;
    const std::string prefix = dir.file("prefix"), build = dir.file("embed"), log = dir.file("log");
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --install " + FLAREKIT_BUILD_DIR + " --prefix " +
                      prefix,
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " -S " + FLAREKIT_EXAMPLE_DIR + " -B " + build +
                      " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + prefix,
                  log),
              0)
        << slurp(log);
    // It found the installed package, not the build tree.
    const std::string cache = slurp(build + "/CMakeCache.txt");
    EXPECT_NE(cache.find("flarekit_DIR:PATH=" + prefix + "/lib/cmake/flarekit"), std::string::npos);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --build " + build, log), 0) << slurp(log);

    const std::string scene = dir.file("city.json"), coverage = dir.file("coverage.json"),
                      rays = dir.file("rays.json");
    ASSERT_EQ(run(build + "/embed-gl --headless --frames 3 --out " + dir.file("frame.ppm") +
                      " --scene-json " + scene + " --coverage-json " + coverage,
                  log),
              0)
        << slurp(log);
    EXPECT_NE(slurp(log).find("255 lights (the sun and 254 lamps)"), std::string::npos)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CLI) + " visibility " + scene +
                      " --method raycast --samples 64 --json",
                  rays),
              0)
        << slurp(rays);
    // The CLI measures the same scene through the same API on flarekit's own renderer.
    const std::string cli = dir.file("cli.json");
    ASSERT_EQ(run(std::string(FLAREKIT_CLI) + " visibility " + scene +
                      " --method compute --msaa 4 --json",
                  cli),
              0)
        << slurp(cli);
    const auto viaCli = nlohmann::json::parse(slurp(cli))["lights"];
    const auto sceneJson = nlohmann::json::parse(slurp(scene));
    const auto engine = nlohmann::json::parse(slurp(coverage))["coverage"];
    const auto truth = nlohmann::json::parse(slurp(rays))["lights"];
    ASSERT_EQ(engine.size(), truth.size());
    const auto& eye = sceneJson["camera"]["position"];
    const double focalPx = double(sceneJson["image"]["height"]) / 2 /
                           std::tan(double(sceneJson["camera"]["fov_y_deg"]) * M_PI / 360);
    int compared = 0, hidden = 0, partial = 0;
    for (std::size_t i = 0; i < engine.size(); ++i) {
        const auto& light = sceneJson["lights"][i];
        double radiusPx = 0;
        if (light["type"] == "point") {
            const auto& p = light["position"];
            const double d =
                std::hypot(double(p[0]) - double(eye[0]), double(p[1]) - double(eye[1]),
                           double(p[2]) - double(eye[2]));
            radiusPx = focalPx * double(light["radius"]) / d;
        } else {
            radiusPx = focalPx * double(light["angular_radius_deg"]) * M_PI / 180;
        }
        if (double(truth[i]["in_frame"]) < 1 || radiusPx < kMinRadiusPx) continue;
        const double t = truth[i]["coverage"];
        EXPECT_NEAR(double(engine[i]), t, depthTolerance(radiusPx))
            << "light " << i << ", " << radiusPx << " px";
        EXPECT_NEAR(double(engine[i]), double(viaCli[i]["coverage"]), depthTolerance(radiusPx))
            << "light " << i << " (the CLI)";
        ++compared;
        hidden += t == 0 ? 1 : 0;
        partial += t > 0.02 && t < 0.98 ? 1 : 0;
    }
    EXPECT_GE(compared, 40);
    EXPECT_GE(hidden, 10);  // lamps behind buildings, and one lamp's bulb before another
    EXPECT_GE(partial, 2);  // the globes at the block corners

    // With a display it opens a window (GLFW, a GLX context) and measures the same.
    {
        const Xvfb x;
        ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
        const std::string windowed = dir.file("windowed.json");
        ASSERT_EQ(run("DISPLAY=" + x.display() + " " + build + "/embed-gl --frames 3 --out " +
                          dir.file("window.ppm") + " --coverage-json " + windowed,
                      log),
                  0)
            << slurp(log);
        EXPECT_NE(slurp(log).find("a 1280x720 window (GLFW)"), std::string::npos) << slurp(log);
        const auto inWindow = nlohmann::json::parse(slurp(windowed))["coverage"];
        ASSERT_EQ(inWindow.size(), engine.size());
        for (std::size_t i = 0; i < engine.size(); ++i)
            EXPECT_NEAR(double(inWindow[i]), double(engine[i]), 1e-4) << "light " << i;
    }

    // C, through pkg-config.
    const std::string exe = dir.file("c_api_check");
    ASSERT_EQ(
        run("PKG_CONFIG_PATH=" + prefix + "/lib/pkgconfig cc -std=c99 -Wall -Werror " +
                FLAREKIT_C_CHECK + " -o " + exe + " $(PKG_CONFIG_PATH=" + prefix +
                "/lib/pkgconfig pkg-config --cflags --libs flarekit) -Wl,-rpath," + prefix + "/lib",
            log),
        0)
        << slurp(log);
    ASSERT_EQ(run(exe, log), 0) << slurp(log);
    EXPECT_NE(slurp(log).find("fk_engine_create: max_lights: expected 1..16384, got 0"),
              std::string::npos)
        << slurp(log);
}

namespace {

//! Whether `needle` occurs anywhere in the file's bytes.
bool fileContains(const std::filesystem::path& file, const std::string& needle) {
    const std::string bytes = slurp(file.string());
    return bytes.find(needle) != std::string::npos;
}

}  // namespace

TEST(Package, AMovedInstallFindsItsOwnFilesLinksNoGplCodeAndBuildsTheCoreExample) {
    namespace fs = std::filesystem;
    TempDir dir;
    const std::string installed = dir.file("prefix"), moved = dir.file("moved"),
                      log = dir.file("log");
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --install " + FLAREKIT_BUILD_DIR + " --prefix " +
                      installed,
                  log),
              0)
        << slurp(log);
    fs::rename(installed, moved);
    // The full set: CLI, libraries, presets, lenses, the OCIO config, docs, examples, licence.
    for (const char* file :
         {"bin/flarekit", "lib/libflarekit.so", "lib/libflarekit_core.a", "lib/libflarekit_gl.a",
          "lib/flarekit/libflarekit_oiio.so", "lib/cmake/flarekit/flarekitConfig.cmake",
          "lib/pkgconfig/flarekit.pc", "lib/pkgconfig/flarekit-core.pc",
          "lib/pkgconfig/flarekit-gl.pc", "share/flarekit/presets/tanczos-classic.json",
          "share/flarekit/presets/postfx/killzone2.json",
          "share/flarekit/presets/lenses/angenieux-double-gauss.json",
          "share/flarekit/presets/ocio/flarekit.ocio", "share/doc/flarekit/LICENSE",
          "share/doc/flarekit/NOTICE", "share/doc/flarekit/architecture.md",
          "share/doc/flarekit/examples/core-apply/main.cpp", "include/flarekit/Flare.h"})
        EXPECT_TRUE(fs::exists(fs::path(moved) / file)) << file;
    // Each installed core header compiles on its own with nothing but the installed include
    // folder: none pulls in OpenGL (those are under flarekit/gl/) or an uninstalled header.
    int coreHeaders = 0;
    // The job layer (job/) and the OCIO transform (ocio/) are core headers too.
    const fs::path includeDir = fs::path(moved) / "include/flarekit";
    for (const auto& entry : fs::recursive_directory_iterator(includeDir)) {
        if (!entry.is_regular_file()) continue;
        const std::string name = fs::relative(entry.path(), includeDir).string();
        if (name == "flarekit.h" || name == "flarekit.hpp") continue;  // the C API's
        if (name.rfind("gl/", 0) == 0) continue;                       // flarekit::gl's
        ++coreHeaders;
        EXPECT_EQ(run("echo '#include <flarekit/" + name +
                          ">' | c++ -std=c++20 -fsyntax-only -x c++ -I" + moved + "/include -",
                      log),
                  0)
            << name << ": " << slurp(log);
        const std::string text = slurp(entry.path().string());
        EXPECT_EQ(text.find("#include \"flarekit/gl/"), std::string::npos) << name;
        EXPECT_EQ(text.find("epoxy"), std::string::npos) << name;
    }
    EXPECT_GE(coreHeaders, 15);
    EXPECT_TRUE(fs::exists(fs::path(moved) / "include/flarekit/gl/HeadlessGl.h"));

    // Nothing of this machine's source or build folders is compiled into what is installed.
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(moved) / "lib")) {
        if (!entry.is_regular_file() || entry.path().extension() == ".cmake" ||
            entry.path().extension() == ".pc")
            continue;
        EXPECT_FALSE(fileContains(entry.path(), FLAREKIT_SOURCE_DIR)) << entry.path();
        EXPECT_FALSE(fileContains(entry.path(), FLAREKIT_BUILD_DIR)) << entry.path();
    }
    EXPECT_FALSE(fileContains(fs::path(moved) / "bin/flarekit", FLAREKIT_SOURCE_DIR));
    EXPECT_FALSE(fileContains(fs::path(moved) / "bin/flarekit", FLAREKIT_BUILD_DIR));

    // The moved CLI finds its presets, lenses, OCIO config and image module with no variable set.
    const std::string cli =
        "env -u FLAREKIT_PRESET_PATH -u FLAREKIT_DATA_DIR -u OCIO "
        "-u FLAREKIT_OIIO_MODULE " +
        moved + "/bin/flarekit";
    const std::string sample = std::string(FLAREKIT_SAMPLES) + "/sunset.png";
    ASSERT_EQ(run(cli + " presets", log), 0) << slurp(log);
    EXPECT_NE(slurp(log).find("tanczos-classic"), std::string::npos) << slurp(log);
    ASSERT_EQ(run(cli + " apply " + sample + " -o " + dir.file("a.bmp") + " --preset starburst " +
                      "--colorspace-in acescg",
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(
        run(cli + " postfx " + sample + " -o " + dir.file("p.png") + " --preset killzone2", log), 0)
        << slurp(log);
    ASSERT_EQ(
        run(cli + " lens render angenieux-double-gauss " + sample + " -o " + dir.file("l.png"),
            log),
        0)
        << slurp(log);
    for (const char* out : {"a.bmp", "p.png", "l.png"})
        EXPECT_GT(fs::file_size(dir.file(out)), 1000u) << out;

    // The README's "Library" example against flarekit::core, through CMake and pkg-config. A
    // program that links the static core finds the shipped presets through FLAREKIT_DATA_DIR
    // (or when it is installed into the same prefix's bin/).
    const std::string build = dir.file("core-apply");
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " -S " + FLAREKIT_CORE_EXAMPLE_DIR + " -B " +
                      build + " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + moved,
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --build " + build, log), 0) << slurp(log);
    const std::string data = "env FLAREKIT_DATA_DIR=" + moved + "/share/flarekit/presets ";
    ASSERT_EQ(run(data + build + "/core-apply " + sample + " " + dir.file("core.exr"), log), 0)
        << slurp(log);
    EXPECT_NE(slurp(log).find("1 light(s) flared"), std::string::npos) << slurp(log);
    const std::string viaPkgConfig = dir.file("core-apply-pc");
    const std::string pc = "PKG_CONFIG_PATH=" + moved + "/lib/pkgconfig ";
    ASSERT_EQ(run("c++ -O1 " + std::string(FLAREKIT_CORE_EXAMPLE_DIR) + "/main.cpp -o " +
                      viaPkgConfig + " $(" + pc + "pkg-config --cflags --libs flarekit-core)",
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(
        run(data + viaPkgConfig + " " + sample + " " + dir.file("core-pc.png") + " subtle", log), 0)
        << slurp(log);
    // A bad preset is the library's one-line error.
    EXPECT_EQ(run(data + viaPkgConfig + " " + sample + " " + dir.file("x.png") + " nonesuch", log),
              2);
    EXPECT_NE(slurp(log).find("preset 'nonesuch': expected a JSON file or one of:"),
              std::string::npos)
        << slurp(log);

    // A front end over the job layer (flarekit::core + flarekit::ocio): a 3-frame sequence with
    // the light found, written in ACEScg, progress through its callback.
    const std::string jobBuild = dir.file("job-apply");
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " -S " + FLAREKIT_JOB_EXAMPLE_DIR + " -B " +
                      jobBuild + " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + moved,
                  log),
              0)
        << slurp(log);
    ASSERT_EQ(run(std::string(FLAREKIT_CMAKE) + " --build " + jobBuild, log), 0) << slurp(log);
    fs::create_directories(dir.file("seq"));
    for (const char* frame : {"seq/in.0001.png", "seq/in.0002.png", "seq/in.0003.png"})
        fs::copy_file(sample, dir.file(frame));
    ASSERT_EQ(run(data + jobBuild + "/job-apply " + dir.file("seq/in.####.png") + " " +
                      dir.file("seq/out.####.exr") + " acescg",
                  log),
              0)
        << slurp(log);
    EXPECT_NE(slurp(log).find("frame 3 of 3 written"), std::string::npos) << slurp(log);
    for (const char* frame : {"seq/out.0001.exr", "seq/out.0002.exr", "seq/out.0003.exr"})
        EXPECT_GT(fs::file_size(dir.file(frame)), 1000u) << frame;

    // Licences: what the installed library, the CLI and a core program link is on the list.
    ASSERT_EQ(
        run(std::string(FLAREKIT_LICENCE_CHECK) + " " + FLAREKIT_LICENCE_ALLOWLIST + " " + moved +
                "/lib/libflarekit.so " + moved + "/bin/flarekit " + build + "/core-apply",
            log),
        0)
        << slurp(log);
    EXPECT_EQ(slurp(log).find("fftw"), std::string::npos) << slurp(log);
    EXPECT_NE(slurp(log).find("libflarekit.so: libtbb.so.12  libtbb12  Apache-2.0"),
              std::string::npos)
        << slurp(log);
}

TEST(Package, TheLicenceCheckRefusesALibraryOffItsList) {
    // The same check with an allow-list lacking zlib fails on the CLI and names the package.
    TempDir dir;
    const std::string list = dir.file("list.tsv"), log = dir.file("log");
    {
        std::ifstream in(FLAREKIT_LICENCE_ALLOWLIST);
        std::ofstream out(list);
        for (std::string line; std::getline(in, line);)
            if (line.rfind("zlib1g", 0) != 0) out << line << "\n";
    }
    EXPECT_EQ(run(std::string(FLAREKIT_LICENCE_CHECK) + " " + list + " " + FLAREKIT_CLI, log), 1);
    EXPECT_NE(slurp(log).find("libz.so.1: package zlib1g is not on the allow-list"),
              std::string::npos)
        << slurp(log);
}
