// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Ghosts pass (included by the GL chain only): ghosts.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/ghosts/Ghosts.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<GhostsUniforms>) {
    return {"ghosts.frag", {shaders::ghosts_frag}};
}

}  // namespace flarekit::postfx
