// SPDX-License-Identifier: Apache-2.0
// The README's "Library" example: a flare on an image through flarekit::core alone (no GL).
//   core-apply IN OUT [PRESET]
#include <flarekit/Flare.h>
#include <flarekit/ImageIO.h>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: core-apply IN OUT [PRESET]\n");
        return 2;
    }
    auto loaded = flarekit::readImage(argv[1]);  // Result<LoadedImage>
    auto preset = flarekit::loadPreset(argc > 3 ? argv[3] : "tanczos-classic");  // Result<Preset>
    if (!loaded || !preset) {  // .error().message is one line
        std::fprintf(stderr, "%s\n", (!loaded ? loaded.error() : preset.error()).message.c_str());
        return 2;
    }
    // The lights `--light auto` finds, each flared by its own flux (flarekit/Flare.h).
    const flarekit::LightSearch lights = flarekit::findLights(loaded->image);
    if (lights.lights.empty()) {
        std::fprintf(stderr, "%s: no light: %s\n", argv[1], lights.whyNone.c_str());
        return 1;
    }
    flarekit::flareLights(loaded->image, *preset, lights);
    const flarekit::Status written = flarekit::writeImage(argv[2], loaded->image);
    if (!written) {
        std::fprintf(stderr, "%s\n", written.error().message.c_str());
        return 2;
    }
    std::printf("%zu light(s) flared into %s\n", lights.lights.size(), argv[2]);
    return 0;
}
