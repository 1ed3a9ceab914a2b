// SPDX-License-Identifier: Apache-2.0
#include "core/DiscMask.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace flarekit {

void markDisc(std::uint8_t* mask, int width, int height, float cx, float cy, float radius) {
    const int x0 = std::max(0, int(std::floor(cx - radius)));
    const int x1 = std::min(width, int(std::ceil(cx + radius)));
    const int y0 = std::max(0, int(std::floor(cy - radius)));
    const int y1 = std::min(height, int(std::ceil(cy + radius)));
    if (x0 >= x1) return;
    const float rr = radius * radius;
    for (int y = y0; y < y1; ++y) {
        const float dy = float(y) + 0.5f - cy;
        if (dy * dy > rr) continue;  // dx * dx + dy * dy >= dy * dy: no pixel of the row
        // Along a row the test's left side falls, then rises, with |dx| (each float operation
        // is monotonic), so its pixels are one span. Its ends from the square root, then moved
        // pixel by pixel until the test itself agrees: the span is exactly the test's.
        const float half = std::sqrt(rr - dy * dy), centre = cx - 0.5f;
        int a = std::clamp(int(std::ceil(centre - half)), x0, x1 - 1);
        int b = std::clamp(int(std::floor(centre + half)), x0, x1 - 1);
        const auto inside = [&](int x) { return inDisc(cx, cy, radius, x, y); };
        while (a > x0 && inside(a - 1)) --a;
        while (a <= b && !inside(a)) ++a;
        while (b < x1 - 1 && inside(b + 1)) ++b;
        while (b >= a && !inside(b)) --b;
        if (a <= b)
            std::memset(mask + std::size_t(y) * std::size_t(width) + std::size_t(a), 1,
                        std::size_t(b - a + 1));
    }
}

}  // namespace flarekit
