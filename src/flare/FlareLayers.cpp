// SPDX-License-Identifier: Apache-2.0
// The sprite flare as compositing layers: each element type to its pass, every pass over black.
#include "flarekit/Flare.h"

namespace flarekit {

int flareLayerOf(ElementType type) {
    switch (type) {
        case ElementType::Glow:
            return 0;
        case ElementType::Ring:
            return 1;
        case ElementType::Disc:
        case ElementType::Polygon:
        case ElementType::Image:  // engines' textured elements are mostly ghosts
            return 2;
        case ElementType::Streaks:
        case ElementType::EdgeStreak:
            return 3;
        case ElementType::Rays:
            return 4;
    }
    return 0;
}

std::vector<FlareLayer> renderFlareLayers(int width, int height, const Preset& preset,
                                          const std::vector<std::pair<Point, float>>& lights,
                                          Image& flare) {
    flare = Image(width, height);
    std::vector<FlareLayer> layers;
    for (int layer = 0; layer < int(std::size(kFlareLayerNames)); ++layer) {
        Preset part = preset;
        part.elements.clear();
        for (const ElementParams& e : preset.elements)
            if (flareLayerOf(e.type) == layer) part.elements.push_back(e);
        if (part.elements.empty()) continue;
        FlareLayer out{kFlareLayerNames[layer], Image(width, height)};
        for (const auto& [light, intensity] : lights)
            if (intensity > 0.f) renderFlare(out.image, part, light, intensity);
        float* sum = flare.data();
        const float* add = out.image.data();
        for (std::size_t i = 0; i < flare.pixelCount() * 4; ++i) sum[i] += add[i];
        layers.push_back(std::move(out));
    }
    return layers;
}

}  // namespace flarekit
