// SPDX-License-Identifier: Apache-2.0
// The one headless GL context of a GL test process. Every GL test calls glContext() first; a
// machine without working headless GL fails here, loudly (tests never skip).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>

#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::test {

inline gl::HeadlessGl& glContext() {
    static auto gl = gl::HeadlessGl::create();
    if (!gl.ok()) {
        ADD_FAILURE() << gl.error().message;
        std::abort();
    }
    return *gl.value();
}

}  // namespace flarekit::test
