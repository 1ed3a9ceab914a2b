// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: post-process preset JSON (parsePostFxPreset) and, for a valid one, the CPU
// chain on a small image, so that every accepted value is one the chain survives.
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/PostFx.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto params = flarekit::parsePostFxPreset(text, "fuzz.json");
    if (!params) return 0;
    flarekit::Image image(24, 16);
    image.fill({4.f, 2.f, 1.f, 1.f});
    (void)flarekit::postFxCpu(image, *params);
    return 0;
}
