// SPDX-License-Identifier: Apache-2.0
// A lens for a test: a shipped prescription by name, or one written in the test. A lens that
// does not load fails the test and gives an empty lens, so the test goes on to report what else
// it finds.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "flarekit/Lens.h"

namespace flarekit::test {

inline Lens shippedLens(const std::string& name) {
    auto lens = loadLens(name);
    EXPECT_TRUE(lens.ok()) << (lens.ok() ? "" : lens.error().message);
    return lens.ok() ? *lens : Lens{};
}

inline Lens parsedLens(const char* text) {
    auto lens = parseLens(text, "lens.json");
    EXPECT_TRUE(lens.ok()) << (lens.ok() ? "" : lens.error().message);
    return lens.ok() ? *lens : Lens{};
}

}  // namespace flarekit::test
