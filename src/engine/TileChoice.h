// SPDX-License-Identifier: Apache-2.0
// Which lights of a view sun-map tiles measure, for both backends: every light with
// texture-mask, and with compute those whose disc covers fewer depth samples than the
// threshold (fk_engine_set_tile_threshold), as light_coverage.comp sizes them.
#pragma once

#include <vector>

#include "flarekit/flarekit.h"

namespace flarekit::engine {

//! tileOf[i]: light i's tile (0, 1, ... in light order) or -1 for the depth. A camera inside a
//! sphere light is never tiled (every method counts it fully seen). Returns the tiles used.
int chooseTiles(const fk_frame& f, int depthSamples, const fk_light* lights, int count, bool every,
                int belowSamples, std::vector<int>& tileOf);

}  // namespace flarekit::engine
