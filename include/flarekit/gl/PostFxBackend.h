// SPDX-License-Identifier: Apache-2.0
// The postfx job's OpenGL backend (flarekit/job/PostFxJob.h): the chain of GpuPostFx in a
// headless context made for each image.
#pragma once

#include <memory>

#include "flarekit/job/PostFxJob.h"

namespace flarekit::gl {

//! How the image moves to and from the GPU: halves where nothing is lost (a half EXR in, a half
//! EXR out), floats, or Auto: halves on a GPU, floats on llvmpipe/softpipe, where the "GPU" is
//! this CPU and halves only add a conversion each way (a 4K read-back: 121 ms as floats, 162 ms
//! as halves).
//! In kGpuTransferNames' order (flarekit/job/PostFxJob.h).
enum class GlTransfer { Auto, Half, Float };

std::shared_ptr<const PostFxBackend> glPostFxBackend(GlTransfer transfer = GlTransfer::Auto);

}  // namespace flarekit::gl
