// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Lens pass (included by the GL chain only): lens.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/composite/Lens.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<LensUniforms>) {
    return {"lens.frag", {shaders::chromatic_glsl, shaders::starburst_glsl, shaders::lens_frag}};
}

}  // namespace flarekit::postfx
