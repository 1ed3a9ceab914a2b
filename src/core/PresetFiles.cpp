// The preset search path and lookup by name, for sprite and post-process presets alike.
#include "core/PresetFiles.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/JsonText.h"
#include "flarekit/Flare.h"

#ifndef FLAREKIT_SOURCE_PRESET_DIR
#define FLAREKIT_SOURCE_PRESET_DIR ""
#endif
#ifndef FLAREKIT_INSTALL_PRESET_DIR
#define FLAREKIT_INSTALL_PRESET_DIR ""
#endif

namespace flarekit {

namespace fs = std::filesystem;

std::vector<std::string> presetSearchPath() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("FLAREKIT_PRESET_PATH")) {
        std::stringstream ss(env);
        for (std::string dir; std::getline(ss, dir, ':');) {
            if (!dir.empty()) dirs.push_back(dir);
        }
    }
    // An install moved to another prefix (`cmake --install build --prefix /opt/flarekit`)
    // keeps bin/ and share/ side by side: look beside the running executable first.
    std::error_code ec;
    const auto addBeside = [&](const fs::path& binary) {
        if (!binary.has_parent_path()) return;
        const fs::path beside =
            binary.parent_path().parent_path() / "share" / "flarekit" / "presets";
        if (fs::is_directory(beside, ec) &&
            std::find(dirs.begin(), dirs.end(), beside.string()) == dirs.end())
            dirs.push_back(beside.string());
    };
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) addBeside(exe);
    // The same beside libflarekit.so (lib/ and share/ of its prefix), for applications that
    // embed the library from wherever it was installed.
    Dl_info library{};
    if (dladdr(reinterpret_cast<void*>(&presetSearchPath), &library) && library.dli_fname)
        addBeside(fs::absolute(fs::path(library.dli_fname), ec));
    for (const char* dir : {FLAREKIT_INSTALL_PRESET_DIR, FLAREKIT_SOURCE_PRESET_DIR}) {
        if (*dir && std::find(dirs.begin(), dirs.end(), std::string(dir)) == dirs.end())
            dirs.emplace_back(dir);
    }
    return dirs;
}

std::vector<std::string> presetNamesIn(const std::string& subdir) {
    std::vector<std::string> names;
    for (const std::string& dir : presetSearchPath()) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(fs::path(dir) / subdir, ec)) {
            if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

Result<std::string> readPresetText(const std::string& nameOrPath, const std::string& subdir,
                                   std::string& path) {
    path = nameOrPath;
    const bool looksLikePath =
        nameOrPath.find('/') != std::string::npos || fs::path(nameOrPath).extension() == ".json";
    if (!looksLikePath) {
        path.clear();
        for (const std::string& dir : presetSearchPath()) {
            const fs::path candidate = fs::path(dir) / subdir / (nameOrPath + ".json");
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) {
                path = candidate.string();
                break;
            }
        }
        if (path.empty()) {
            std::string names;
            for (const std::string& n : presetNamesIn(subdir))
                names += (names.empty() ? "" : ", ") + n;
            return invalidInput((subdir.empty() ? "preset '" : subdir + " preset '") + nameOrPath +
                                "': expected a JSON file or one of: " +
                                (names.empty() ? "(no shipped presets found)" : names));
        }
    }
    return readTextFile(path);
}

}  // namespace flarekit
