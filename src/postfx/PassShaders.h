// SPDX-License-Identifier: Apache-2.0
// The GLSL of every pass in PassList.h (GL chain only): each folder's *Gl.h, whose passShader
// overload the GL executor links one program from per PassUniforms alternative.
#pragma once

#include "postfx/blur/UpsampleGl.h"
#include "postfx/brightpass/BrightPassGl.h"
#include "postfx/composite/CompositeGl.h"
#include "postfx/composite/LensGl.h"
#include "postfx/downsample/DownsampleGl.h"
#include "postfx/ghosts/GhostsGl.h"
#include "postfx/halo/HaloGl.h"
#include "postfx/streaks/StreaksGl.h"
