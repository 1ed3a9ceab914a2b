// `--light auto`: find the brightest region of an image. Luminance is computed once; only
// pixels near the peak are visited by the flood fill, so the cost is one pass over the image.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"

namespace flarekit {

float flareScaleForBrightness(float brightness) {
    return brightness <= 1.f ? brightness : 1.f + std::log(brightness);
}

FoundLight findLight(const Image& image, const LightSearchOptions& options) {
    FoundLight result;
    if (image.empty()) return result;
    const int w = image.width(), h = image.height();
    std::vector<float> lum(image.pixelCount());
    parallelFor(0, h, 32, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const Rgba* row = &image.at(0, y);
            for (int x = 0; x < w; ++x) {
                const float l = luminance(row[x].r, row[x].g, row[x].b);
                lum[std::size_t(y) * std::size_t(w) + std::size_t(x)] = std::isfinite(l) ? l : 0.f;
            }
        }
    });
    result.peak = *std::max_element(lum.begin(), lum.end());
    if (!(result.peak >= options.minLuminance)) return result;
    const float threshold = options.nearPeak * result.peak;

    // Connected regions (4-neighbours) above the threshold; keep the one with the most light.
    std::vector<std::uint8_t> seen(lum.size(), 0);
    std::vector<std::size_t> stack;
    double bestSum = -1.0;
    for (std::size_t start = 0; start < lum.size(); ++start) {
        if (seen[start] || lum[start] < threshold) continue;
        double sum = 0, sx = 0, sy = 0;
        std::size_t count = 0;
        seen[start] = 1;
        stack.push_back(start);
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
            sum += lum[i];
            sx += lum[i] * (x + 0.5);
            sy += lum[i] * (y + 0.5);
            ++count;
            auto visit = [&](int nx, int ny) {
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) return;
                const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                if (!seen[j] && lum[j] >= threshold) {
                    seen[j] = 1;
                    stack.push_back(j);
                }
            };
            visit(x - 1, y);
            visit(x + 1, y);
            visit(x, y - 1);
            visit(x, y + 1);
        }
        if (sum > bestSum) {
            bestSum = sum;
            result.position = {float(sx / sum), float(sy / sum)};
            result.pixels = count;
            result.brightness = float(sum / double(count));
        }
    }
    result.found = true;
    result.flareScale = flareScaleForBrightness(result.brightness);
    return result;
}

}  // namespace flarekit
