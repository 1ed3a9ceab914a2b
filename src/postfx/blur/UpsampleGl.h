// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Upsample pass (included by the GL chain only): upsample.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/blur/Upsample.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<UpsampleUniforms>) {
    return {"upsample.frag", {shaders::upsample_frag}};
}

}  // namespace flarekit::postfx
