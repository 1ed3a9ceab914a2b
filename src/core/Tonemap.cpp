#include "flarekit/Tonemap.h"

#include <algorithm>

#include "core/Parallel.h"

namespace flarekit {

void tonemapAcesFitted(Image& image, float exposure) {
    parallelFor(0, image.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = image.row(y);
            for (int i = 0; i < image.width() * 4; ++i) {
                if (i % 4 == 3) continue;  // alpha untouched
                const float x = std::max(0.f, p[i] * exposure);
                p[i] = std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.f, 1.f);
            }
        }
    });
}

}  // namespace flarekit
