// SPDX-License-Identifier: Apache-2.0
#include "occlusion/readback/DepthCoverage.h"

namespace flarekit::occlusion {

namespace {
template <typename SkyOf>
double weightedCoverage(const SunDiscView& v, const float* values, int x0, int y0, int w, int h,
                        SkyOf skyOf) {
    double visible = 0, total = 0;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            const double weight = discWeight(v, x0 + i, y0 + j);
            total += weight;
            visible += weight * skyOf(values[std::size_t(j) * std::size_t(w) + std::size_t(i)]);
        }
    }
    return total > 0 ? visible / total : 0.0;
}
}  // namespace

double coverageFromDepth(const SunDiscView& v, const float* depth, int x0, int y0, int w, int h) {
    const float light = float(v.lightDepth);
    return weightedCoverage(v, depth, x0, y0, w, h,
                            [light](float d) { return d >= light ? 1.0 : 0.0; });
}

double coverageFromSkyFraction(const SunDiscView& v, const float* sky, int x0, int y0, int w,
                               int h) {
    return weightedCoverage(v, sky, x0, y0, w, h, [](float s) { return double(s); });
}

}  // namespace flarekit::occlusion
