// SPDX-License-Identifier: Apache-2.0
// `lens render --backend gl`: the ghost meshes of renderLensFlare traced on the CPU as there,
// and rasterised by OpenGL (additive, RGBA32F), with the same masks and weights line for line
// (src/lens/shaders/lens_ghost.frag against src/lens/LensRender.cpp). The starburst and glare
// are the CPU's. A GL context must be current.
#pragma once

#include <vector>

#include "flarekit/Lens.h"

namespace flarekit {

struct LensGlTimes {
    double ghostsGpuMs = 0;  //!< GPU time of the ghost draws (timer queries)
    double readbackMs = 0;   //!< wall time of reading the ghost layer back
};

Result<LensFlareLayers> renderLensFlareGl(const Lens& lens, int width, int height,
                                          const std::vector<LensLight>& lights,
                                          const LensRenderOptions& options,
                                          LensGlTimes* times = nullptr);

}  // namespace flarekit
