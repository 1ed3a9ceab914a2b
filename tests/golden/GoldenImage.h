// SPDX-License-Identifier: Apache-2.0
// Golden-image checks: an image (linear light, display-referred after its own tone map) is
// encoded to 8-bit sRGB and compared with tests/golden/ref/NAME.png. On a mismatch the test
// writes NAME.actual.png and NAME.diff.png (|difference| x 16) into the golden output folder
// and prints their paths. FLAREKIT_UPDATE_GOLDEN=1 rewrites the references instead
// (tests/golden/README.md).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "flarekit/Color.h"
#include "flarekit/Image.h"
#include "flarekit/ImageIO.h"

namespace golden {

//! How far an actual image may sit from its reference, in 8-bit sRGB levels.
struct Tolerance {
    int maxLevels = 1;            //!< no channel of any pixel further than this
    double maxMeanLevels = 0.02;  //!< mean |difference| over all channels
};

inline flarekit::Image8 encode(const flarekit::Image& linear) {
    flarekit::Image8 out{linear.width(), linear.height(), 3, {}};
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * 3);
    for (int y = 0; y < linear.height(); ++y) {
        for (int x = 0; x < linear.width(); ++x) {
            const flarekit::Rgba& p = linear.at(x, y);
            std::uint8_t* o =
                &out.pixels[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 3];
            o[0] = flarekit::linearToSrgb8(p.r), o[1] = flarekit::linearToSrgb8(p.g),
            o[2] = flarekit::linearToSrgb8(p.b);
        }
    }
    return out;
}

inline std::string referencePath(const std::string& name) {
    return std::string(FLAREKIT_GOLDEN_REF) + "/" + name + ".png";
}
inline std::string outputPath(const std::string& name, const char* kind) {
    std::filesystem::create_directories(FLAREKIT_GOLDEN_OUT);
    return std::string(FLAREKIT_GOLDEN_OUT) + "/" + name + "." + kind + ".png";
}

inline void expectMatches(const std::string& name, const flarekit::Image& linear,
                          Tolerance tolerance = {}) {
    const flarekit::Image8 actual = encode(linear);
    if (const char* update = std::getenv("FLAREKIT_UPDATE_GOLDEN");
        update && std::string(update) == "1") {
        ASSERT_TRUE(flarekit::writeImage8(referencePath(name), actual).ok()) << referencePath(name);
        std::printf("golden: wrote %s\n", referencePath(name).c_str());
        return;
    }
    auto reference = flarekit::readImage8(referencePath(name));
    ASSERT_TRUE(reference.ok()) << name << ": no reference (" << reference.error().message
                                << "); FLAREKIT_UPDATE_GOLDEN=1 writes it";
    ASSERT_EQ(reference->width, actual.width) << name;
    ASSERT_EQ(reference->height, actual.height) << name;
    ASSERT_EQ(reference->channels, 3) << name;
    int worst = 0;
    double sum = 0;
    flarekit::Image8 diff = actual;
    for (std::size_t i = 0; i < actual.pixels.size(); ++i) {
        const int d = std::abs(int(actual.pixels[i]) - int(reference->pixels[i]));
        worst = std::max(worst, d);
        sum += d;
        diff.pixels[i] = std::uint8_t(std::min(255, d * 16));
    }
    const double mean = sum / double(actual.pixels.size());
    const bool ok = worst <= tolerance.maxLevels && mean <= tolerance.maxMeanLevels;
    EXPECT_TRUE(ok) << name << ": worst " << worst << " levels (allowed " << tolerance.maxLevels
                    << "), mean " << mean << " (allowed " << tolerance.maxMeanLevels << ")";
    if (!ok) {
        const std::string a = outputPath(name, "actual"), d = outputPath(name, "diff");
        (void)flarekit::writeImage8(a, actual);
        (void)flarekit::writeImage8(d, diff);
        std::printf("golden: %s differs; actual %s, diff %s, reference %s\n", name.c_str(),
                    a.c_str(), d.c_str(), referencePath(name).c_str());
    }
}

}  // namespace golden
