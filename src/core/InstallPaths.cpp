// SPDX-License-Identifier: Apache-2.0
#include "core/InstallPaths.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>

// The install layout, as paths relative to the folder of the installed executable and of the
// installed shared library (src/CMakeLists.txt computes them from GNUInstallDirs): relative, so
// nothing of the build machine is in the binaries.
#ifndef FLAREKIT_BIN_TO_PRESETS
#define FLAREKIT_BIN_TO_PRESETS "../share/flarekit/presets"
#endif
#ifndef FLAREKIT_LIB_TO_PRESETS
#define FLAREKIT_LIB_TO_PRESETS "../share/flarekit/presets"
#endif
#ifndef FLAREKIT_BIN_TO_MODULES
#define FLAREKIT_BIN_TO_MODULES "../lib/flarekit"
#endif
#ifndef FLAREKIT_LIB_TO_MODULES
#define FLAREKIT_LIB_TO_MODULES "flarekit"
#endif

namespace flarekit {

namespace fs = std::filesystem;

namespace {

fs::path runningExecutable() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe;
}

//! The shared library this code was linked into, or empty when it is in the executable itself
//! (the static core linked into a program: then the executable's prefix is the one).
fs::path containingSharedLibrary() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&containingSharedLibrary), &info) || !info.dli_fname)
        return {};
    std::error_code ec;
    const fs::path library = fs::weakly_canonical(fs::path(info.dli_fname), ec);
    const fs::path exe = runningExecutable();
    if (ec || library.empty() || fs::equivalent(library, exe, ec)) return {};
    return library;
}

struct BuildTree {
    fs::path source, binary;
};

//! When the executable runs from flarekit's own build tree (the CLI, the tests, the benches),
//! that tree's CMakeCache.txt, found at most three folders up, names the source and build
//! folders. An installed executable has no such file above it.
std::optional<BuildTree> buildTreeAbove(fs::path dir) {
    for (int up = 0; up < 4 && !dir.empty(); ++up, dir = dir.parent_path()) {
        std::ifstream cache(dir / "CMakeCache.txt");
        if (!cache) continue;
        BuildTree tree;
        for (std::string line; std::getline(cache, line);) {
            for (const auto& [key, field] :
                 {std::pair{"flarekit_SOURCE_DIR:STATIC=", &tree.source},
                  std::pair{"flarekit_BINARY_DIR:STATIC=", &tree.binary}}) {
                if (line.rfind(key, 0) == 0) *field = line.substr(std::string(key).size());
            }
        }
        if (!tree.source.empty() && !tree.binary.empty()) return tree;
        if (dir == dir.parent_path()) break;
    }
    return std::nullopt;
}
//! The build tree above the executable, else above the shared library this code is in (the
//! Python module in build/python/flarekit/ run by the system's python3).
std::optional<BuildTree> buildTree(const fs::path& library) {
    if (auto tree = buildTreeAbove(runningExecutable().parent_path())) return tree;
    if (!library.empty()) return buildTreeAbove(library.parent_path());
    return std::nullopt;
}

//! Where this process runs from: fixed for its life, so found once (the build tree's lookup
//! reads CMakeCache.txt) rather than on every preset, lens or module lookup.
struct Locations {
    fs::path exe, library;
    std::optional<BuildTree> tree;
};
const Locations& locations() {
    static const Locations found = [] {
        const fs::path library = containingSharedLibrary();
        return Locations{runningExecutable(), library, buildTree(library)};
    }();
    return found;
}

//! Roots a front end added (addShippedRoots), searched after the executable's and library's.
struct AddedRoots {
    std::mutex mutex;
    std::vector<fs::path> presets, modules;
};
AddedRoots& addedRoots() {
    static AddedRoots roots;
    return roots;
}

void addFolder(std::vector<fs::path>& out, const fs::path& dir) {
    std::error_code ec;
    if (dir.empty() || !fs::is_directory(dir, ec)) return;
    const fs::path clean = fs::weakly_canonical(dir, ec);
    if (std::find(out.begin(), out.end(), clean) == out.end()) out.push_back(clean);
}

}  // namespace

std::vector<fs::path> shippedPresetRoots() {
    std::vector<fs::path> roots;
    if (const char* env = std::getenv("FLAREKIT_DATA_DIR"); env && *env) addFolder(roots, env);
    const Locations& at = locations();
    if (!at.exe.empty()) addFolder(roots, at.exe.parent_path() / FLAREKIT_BIN_TO_PRESETS);
    if (!at.library.empty()) addFolder(roots, at.library.parent_path() / FLAREKIT_LIB_TO_PRESETS);
    {
        std::lock_guard lock(addedRoots().mutex);
        for (const fs::path& dir : addedRoots().presets) addFolder(roots, dir);
    }
    if (at.tree) addFolder(roots, at.tree->source / "presets");
    return roots;
}

fs::path shippedOcioConfig() {
    for (const fs::path& root : shippedPresetRoots()) {
        std::error_code ec;
        const fs::path config = root / "ocio" / "flarekit.ocio";
        if (fs::is_regular_file(config, ec)) return config;
    }
    return {};
}

std::vector<fs::path> oiioModuleCandidates() {
    constexpr const char* kModule = "libflarekit_oiio.so";
    std::vector<fs::path> out;
    const Locations& at = locations();
    if (!at.exe.empty()) out.push_back(at.exe.parent_path() / FLAREKIT_BIN_TO_MODULES / kModule);
    if (!at.library.empty())
        out.push_back(at.library.parent_path() / FLAREKIT_LIB_TO_MODULES / kModule);
    {
        std::lock_guard lock(addedRoots().mutex);
        for (const fs::path& dir : addedRoots().modules) out.push_back(dir / kModule);
    }
    if (at.tree) out.push_back(at.tree->binary / "src" / kModule);
    return out;
}

void addShippedRoots(const fs::path& presets, const fs::path& modules) {
    std::lock_guard lock(addedRoots().mutex);
    addedRoots().presets.push_back(presets);
    addedRoots().modules.push_back(modules);
}

}  // namespace flarekit
