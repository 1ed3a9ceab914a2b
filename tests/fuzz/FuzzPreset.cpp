// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: sprite-flare preset JSON (parsePreset), every field validated.
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/Flare.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto preset = flarekit::parsePreset(text, "fuzz.json");
    if (preset) (void)flarekit::flareSpikeWork(*preset, 64, 64);
    return 0;
}
