#include "occlusion/readback/DepthCoverage.h"

namespace flarekit::occlusion {

double coverageFromDepth(const SunDiscView& v, const float* depth, int x0, int y0, int w, int h) {
    double visible = 0, total = 0;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            const double weight = discWeight(v, x0 + i, y0 + j);
            total += weight;
            if (depth[std::size_t(j) * std::size_t(w) + std::size_t(i)] >= 1.0f) visible += weight;
        }
    }
    return total > 0 ? visible / total : 0.0;
}

}  // namespace flarekit::occlusion
