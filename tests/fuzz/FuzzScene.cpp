// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: Scene JSON (parseScene) and, for a valid scene, its lights and a ray-cast
// coverage at a handful of rays per light, so the ground truth survives every accepted scene.
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/Scene.h"
#include "flarekit/Visibility.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto scene = flarekit::parseScene(text, "fuzz.json");
    if (!scene) return 0;
    // Small enough that a fuzzed scene of thousands of objects still runs in milliseconds.
    if (scene->spheres.size() + scene->boxes.size() + scene->triangles.size() > 4096) return 0;
    flarekit::RaycastOptions options;
    options.samplesPerSide = 2;
    (void)flarekit::raycastVisibility(*scene, options);
    return 0;
}
