// SPDX-License-Identifier: Apache-2.0
// The preset search path and lookup by name, for sprite and post-process presets alike.
#include "core/PresetFiles.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/InstallPaths.h"
#include "core/JsonText.h"
#include "flarekit/Flare.h"

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
    // Then the shipped presets of this install, wherever its prefix is (core/InstallPaths.h).
    for (const fs::path& root : shippedPresetRoots()) {
        if (std::find(dirs.begin(), dirs.end(), root.string()) == dirs.end())
            dirs.push_back(root.string());
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
