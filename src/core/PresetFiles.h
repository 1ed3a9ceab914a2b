// SPDX-License-Identifier: Apache-2.0
// Finding shipped presets: the sprite presets in each directory of presetSearchPath(), the
// post-process ones in its postfx/ subdirectory. Shared by Preset.cpp and postfx/PostFxParams.cpp.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Result.h"

namespace flarekit {

//! Sorted, de-duplicated names of the .json files in `subdir` ("" or "postfx") of the search path.
std::vector<std::string> presetNamesIn(const std::string& subdir);

//! The text of a shipped preset (a name, looked up in `subdir`) or of a file (a path, or a name
//! ending in .json); `path` receives the file read, for error messages.
Result<std::string> readPresetText(const std::string& nameOrPath, const std::string& subdir,
                                   std::string& path);

//! A preset by name (in `subdir`) or path, through `parse(text, path)`: the load of every kind.
template <class Parse>
auto loadPresetFile(const std::string& nameOrPath, const std::string& subdir, Parse parse)
    -> decltype(parse(std::string(), std::string())) {
    std::string path;
    auto text = readPresetText(nameOrPath, subdir, path);
    if (!text) return text.error();
    return parse(*text, path);
}

}  // namespace flarekit
