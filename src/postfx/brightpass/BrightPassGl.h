// SPDX-License-Identifier: Apache-2.0
// The GLSL of the BrightPass pass (included by the GL chain only): bright_pass.frag and what it
// needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/brightpass/BrightPass.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<BrightUniforms>) {
    return {"bright_pass.frag", {shaders::bright_pass_frag}};
}

}  // namespace flarekit::postfx
