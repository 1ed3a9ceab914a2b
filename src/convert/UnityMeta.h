// SPDX-License-Identifier: Apache-2.0
// Unity references a texture by the GUID in the .meta file beside it: finding a texture by its
// GUID, and a .meta for a texture written beside an exported asset.
#pragma once

#include <map>

#include "convert/ConvertCommon.h"

namespace flarekit::convert {

//! The GUID a .meta file names, or "" when it has none (or does not exist).
std::string unityGuidOfMeta(const fs::path& meta);
//! GUID -> texture path, from the .meta files under `roots` (at most kMaxMetaFiles files read).
std::map<std::string, std::string> indexUnityTextures(const std::vector<fs::path>& roots);
//! Where a Unity asset's textures are looked for: `assets` when given, else the asset's folder
//! and its parents up to (and including) the project's Assets folder, at most four levels up.
std::vector<fs::path> unityTextureRoots(const fs::path& assetDir, const std::string& assets);
//! A GUID for a file written beside an export: 32 hex digits from its name and the output's
//! path (stable across runs, so re-exporting does not break the project's references).
std::string unityGuidFor(const std::string& outputPath, const std::string& name);
//! The .meta Unity needs to import a texture with that GUID (importer settings: Unity's own
//! defaults for a texture).
std::string unityTextureMeta(const std::string& guid);

}  // namespace flarekit::convert
