// SPDX-License-Identifier: Apache-2.0
// The GLSL of the Downsample pass (included by the GL chain only): downsample.frag and what it
// needs.
#pragma once

#include "flarekit_shaders.h"
#include "postfx/PassShader.h"
#include "postfx/downsample/Downsample.h"

namespace flarekit::postfx {

inline PassShader passShader(std::type_identity<DownsampleUniforms>) {
    return {"downsample.frag", {shaders::downsample_frag}};
}

}  // namespace flarekit::postfx
