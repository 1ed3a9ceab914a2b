// SPDX-License-Identifier: Apache-2.0
// The lens job's OpenGL backend (flarekit/job/LensJob.h): the ghost meshes rasterised by
// OpenGL 4.5 in a headless context made for each image.
#pragma once

#include <memory>

#include "flarekit/job/LensJob.h"

namespace flarekit::gl {

std::shared_ptr<const LensBackend> glLensBackend();

}  // namespace flarekit::gl
