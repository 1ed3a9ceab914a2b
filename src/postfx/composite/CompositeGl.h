// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Composite pass (included by the GL chain only): composite.frag and what it needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/composite/Composite.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<CompositeUniforms>) {
    return {"composite.frag",
            {shaders::tone_curves_glsl, shaders::tone_map_glsl, shaders::composite_frag}};
}

}  // namespace flarekit::postfx
