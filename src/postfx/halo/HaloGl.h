// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Halo pass (included by the GL chain only): halo.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/halo/Halo.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<HaloUniforms>) {
    return {"halo.frag", {shaders::halo_frag}};
}

}  // namespace flarekit::postfx
