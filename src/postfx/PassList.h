// SPDX-License-Identifier: Apache-2.0
// Every pass of the post-process chain, as the type of its uniforms. A pass is one unit in its
// folder (uniforms, CPU pixel kernel passPixel, GLSL, uniform binding bindUniforms, and in
// *Gl.h the shader to link); adding one = its folder + its line here (and its include), its
// *Gl.h include in PassShaders.h and its steps in wireChain (ChainPlan.cpp). Both executors
// (Chain.cpp, GpuChain.cpp) dispatch on this list and do not change.
#pragma once

#include <variant>

#include "postfx/blur/Upsample.h"
#include "postfx/brightpass/BrightPass.h"
#include "postfx/composite/Composite.h"
#include "postfx/composite/Lens.h"
#include "postfx/downsample/Downsample.h"
#include "postfx/ghosts/Ghosts.h"
#include "postfx/halo/Halo.h"
#include "postfx/streaks/Streaks.h"

namespace flarekit::postfx {

//! A step that writes black: the buffer of a pass that is off, read as "no light" downstream.
struct ClearStep {};

using PassUniforms =
    std::variant<ClearStep, BrightUniforms, DownsampleUniforms, UpsampleUniforms, GhostsUniforms,
                 HaloUniforms, StreakUniforms, LensUniforms, CompositeUniforms>;

}  // namespace flarekit::postfx
