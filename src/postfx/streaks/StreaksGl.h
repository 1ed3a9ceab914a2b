// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Streaks pass (included by the GL chain only): streaks.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/streaks/Streaks.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<StreakUniforms>) {
    return {"streaks.frag", {shaders::streaks_frag}};
}

}  // namespace flarekit::postfx
