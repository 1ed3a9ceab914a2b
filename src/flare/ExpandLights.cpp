// SPDX-License-Identifier: Apache-2.0
// Highlight expansion gated by the light finder: an 8-bit photo's clipped lights get their
// energy back, its near-white plateaus (sky, snow, walls) do not.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Parallel.h"
#include "core/Smoothstep.h"
#include "flarekit/Flare.h"
#include "flarekit/Tonemap.h"

namespace flarekit {

namespace {

//! The reach of a light's expansion: full within twice its radius plus 4 px (the disc the
//! finder keeps out of the search as the light's own glare), easing to 0 at kFadeReach times it.
constexpr float kReachRadii = 2.f, kReachSlackPx = 4.f, kFadeReach = 1.5f;
//! The largest core a light is expanded over, as a share of the frame height: the sun's 0.53
//! degree disc is 1% of the height in radius through a 50 mm lens on full frame, 5% through
//! 250 mm. A photo's clipped region around a low sun is often larger (its glare clips too: 117
//! px of a 512-high sunset); expanded whole at the gain it carried dozens of suns' energy, and
//! any bloom pushed the near-white sky around it to white (3.4-6.3% of blender-data's sunset
//! as an 8-bit photo newly clipped; 0.4-1.1% with this bound, and 8% lets 2.4% through). The
//! expansion is centred on the light's centroid over at most this radius; the rest of the
//! clipped glare stays as it is.
constexpr float kMaxExpandedCoreOfHeight = 0.05f;

}  // namespace

LightSearch expandHighlightsAtLights(Image& image, float gain, LightSearchOptions options) {
    options.maxLights = kMaxExpandedLights;
    LightSearch search = findLights(image, options);
    if (search.lights.empty()) return search;
    // Each pixel's nearness to the nearest light, filled light by light over its own box only.
    const int w = image.width(), h = image.height();
    std::vector<float> nearness(std::size_t(w) * std::size_t(h), 0.f);
    for (const LightCandidate& l : search.lights) {
        const float core = std::min(l.radius, kMaxExpandedCoreOfHeight * float(h));
        const float reach = kReachRadii * core + kReachSlackPx, outer = kFadeReach * reach;
        const int x0 = std::max(0, int(std::floor(l.position.x - outer))),
                  x1 = std::min(w - 1, int(std::ceil(l.position.x + outer))),
                  y0 = std::max(0, int(std::floor(l.position.y - outer))),
                  y1 = std::min(h - 1, int(std::ceil(l.position.y + outer)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float d =
                    std::hypot(float(x) + 0.5f - l.position.x, float(y) + 0.5f - l.position.y);
                float& n = nearness[std::size_t(y) * std::size_t(w) + std::size_t(x)];
                n = std::max(n, 1.f - smoothstep01((d - reach) / (outer - reach)));
            }
    }
    parallelFor(0, h, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = image.row(y);
            const float* near = &nearness[std::size_t(y) * std::size_t(w)];
            for (int x = 0; x < w; ++x, p += 4) {
                if (near[x] <= 0.f) continue;
                const float m = std::max({p[0], p[1], p[2]});
                const float s = std::clamp((m - kExpandKnee) / (1.f - kExpandKnee), 0.f, 1.f);
                const float factor = 1.f + (gain - 1.f) * s * s * near[x];
                p[0] *= factor, p[1] *= factor, p[2] *= factor;
            }
        }
    });
    return search;
}

}  // namespace flarekit
