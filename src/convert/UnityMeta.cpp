// SPDX-License-Identifier: Apache-2.0
#include "convert/UnityMeta.h"

#include <cstdint>
#include <fstream>
#include <functional>

namespace flarekit::convert {

namespace {
//! .meta files read while looking for textures: a large project's Assets folder has ~10^4, and
//! reading more would make a conversion slow without finding anything a flare asset uses.
constexpr std::size_t kMaxMetaFiles = 20000;

}  // namespace

std::string unityGuidOfMeta(const fs::path& meta) {
    std::ifstream in(meta);
    std::string line;
    for (int i = 0; i < 4 && std::getline(in, line); ++i) {
        if (line.rfind("guid: ", 0) == 0) return line.substr(6, 32);
    }
    return {};
}

std::map<std::string, std::string> indexUnityTextures(const std::vector<fs::path>& roots) {
    std::map<std::string, std::string> index;
    std::size_t seen = 0;
    for (const fs::path& root : roots) {
        std::error_code ec;
        fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied,
                                            ec);
        for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            if (it->path().extension() != ".meta" || !it->is_regular_file(ec)) continue;
            if (++seen > kMaxMetaFiles) return index;
            const std::string guid = unityGuidOfMeta(it->path());
            fs::path target = it->path();
            target.replace_extension();  // "flare.png.meta" -> "flare.png"
            if (!guid.empty() && fs::is_regular_file(target, ec))
                index.emplace(guid, fs::absolute(target, ec).string());
        }
    }
    return index;
}

std::vector<fs::path> unityTextureRoots(const fs::path& assetDir, const std::string& assets) {
    if (!assets.empty()) return {fs::path(assets)};
    fs::path dir = assetDir.empty() ? fs::path(".") : assetDir;
    std::vector<fs::path> roots{dir};
    for (int up = 0; up < 4 && dir.has_parent_path() && dir.filename() != "Assets"; ++up) {
        dir = dir.parent_path();
        if (dir.filename() == "Assets") roots = {dir};
    }
    return roots;
}

std::string unityGuidFor(const std::string& outputPath, const std::string& name) {
    // Two FNV-1a 64-bit hashes (different offsets) of the folder and the name: 128 bits.
    auto fnv = [](std::uint64_t h, const std::string& s) {
        for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
        return h;
    };
    const std::string key = fs::absolute(fs::path(outputPath)).parent_path().string() + "/" + name;
    const std::uint64_t a = fnv(14695981039346656037ull, key), b = fnv(0x9e3779b97f4a7c15ull, key);
    char hex[33];
    std::snprintf(hex, sizeof hex, "%016llx%016llx", (unsigned long long)a, (unsigned long long)b);
    return hex;
}

std::string unityTextureMeta(const std::string& guid) {
    return "fileFormatVersion: 2\nguid: " + guid +
           "\nTextureImporter:\n  serializedVersion: 12\n  mipmaps:\n    enableMipMap: 1\n"
           "  textureType: 0\n  alphaIsTransparency: 0\n  wrapU: 1\n  wrapV: 1\n";
}

}  // namespace flarekit::convert
