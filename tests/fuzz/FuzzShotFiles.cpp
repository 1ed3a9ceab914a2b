// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the shot's text inputs a user or a pipeline hands the CLI. The first byte
// picks the reader: a light track (CSV or JSON), a camera track (JSON), a lens prescription
// (JSON), a frame pattern (--frames' shot.####.exr) or a frame range (--frames 1001-1100x2);
// the rest is the text. Each must return a value or one error, within the limits, never crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzLimits.h"
#include "flarekit/Lens.h"
#include "flarekit/Shot.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    flarekit::fuzz::setLimits();
    if (size < 1) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    switch (data[0] % 5) {
        case 0:
            (void)flarekit::parseLightTrack(text, "fuzz.csv");
            break;
        case 1:
            (void)flarekit::parseCameraTrack(text, "fuzz.json");
            break;
        case 2:
            (void)flarekit::parseLens(text, "fuzz.json");
            break;
        case 3:
            (void)flarekit::parseFramePattern(text);
            break;
        default:
            (void)flarekit::parseFrameRange(text, "--frames");
            break;
    }
    return 0;
}
