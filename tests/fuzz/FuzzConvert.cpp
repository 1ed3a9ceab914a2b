// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: flarekit convert's readers (importFlare) on every format. The input's first
// byte picks the file's extension (its format), the rest is the file: JSON (flarekit, PlayCanvas,
// Babylon.js, three.js, Unreal, Godot, detected by keys), a Unity .asset (YAML), a Godot .tscn,
// Unreal .ini text. What it reads is written back as flarekit JSON, exercising the writer too.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/Convert.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".json", ".asset", ".tscn", ".ini"};
    static const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                             ("flarekit-fuzz-convert-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string in = (dir / (std::string("in") + kExtensions[data[0] % 4])).string();
    std::ofstream(in, std::ios::binary)
        .write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    auto asset = flarekit::importFlare(in);
    if (asset)
        (void)flarekit::exportFlare(*asset, (dir / "out.json").string(),
                                    flarekit::FlareFormat::Flarekit);
    return 0;
}
