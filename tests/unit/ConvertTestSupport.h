// SPDX-License-Identifier: Apache-2.0
// What the converter's tests share: the engines' fixtures (examples/interop), files written
// and read back, and small Unity assets.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "flarekit/Convert.h"
#include "flarekit/ImageIO.h"

namespace flarekit::test {

inline const std::string kInterop = std::string(FLAREKIT_SOURCE_DIR) + "/examples/interop";

inline std::string slurp(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline void spit(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

inline ConvertOptions toFormat(FlareFormat f) {
    ConvertOptions o;
    o.to = f;
    return o;
}
inline ConvertOptions fromFormat(FlareFormat f) {
    ConvertOptions o;
    o.from = f;
    return o;
}

//! A white 16x16 square texture, so an image element covers exactly its quad.
inline bool writeSquareTexture(const std::string& path) {
    Image square(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) square.at(x, y) = {1, 1, 1, 1};
    return writeImage(path, square).ok();
}

//! A Unity Lens Flare (SRP) asset of one element (its YAML keys, indented as a list item's).
inline std::string unityAsset(const std::string& element) {
    return "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &11400000\nMonoBehaviour:\n"
           "  m_Name: t\n  elements:\n  - " +
           element + "\n";
}

//! A shipped sprite preset as the converter's asset.
inline FlareAsset shippedSpriteAsset(const std::string& name) {
    FlareAsset asset;
    if (auto preset = loadPreset(name)) asset.sprite = *preset;
    return asset;
}

}  // namespace flarekit::test
