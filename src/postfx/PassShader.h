// SPDX-License-Identifier: Apache-2.0
// What the GL chain links for a pass: the fragment shader's name (for messages) and its parts,
// appended after the shared sizes and postfx_common.glsl. Each pass folder's *Gl.h says it.
#pragma once

#include <type_traits>
#include <vector>

namespace flarekit::postfx {

struct PassShader {
    const char* name;
    std::vector<const char*> parts;
};

}  // namespace flarekit::postfx
