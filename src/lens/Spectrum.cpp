// SPDX-License-Identifier: Apache-2.0
#include "lens/Spectrum.h"

#include <cmath>

#include "flarekit/Lens.h"

namespace flarekit::lens {

namespace {
//! A Gaussian with different widths left and right of its peak (the fit's lobe).
double lobe(double x, double mu, double left, double right) {
    const double t = (x - mu) / (x < mu ? left : right);
    return std::exp(-0.5 * t * t);
}
}  // namespace

std::array<double, 3> cieXyz(double l) {
    return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

std::vector<SpectralSample> spectralSamples(int count) {
    std::vector<SpectralSample> out;
    if (count <= 0) {
        for (int c = 0; c < 3; ++c) {
            SpectralSample s;
            s.lambdaNm = kRgbWavelengthsNm[std::size_t(c)];
            s.weight[std::size_t(c)] = 1.0;
            out.push_back(s);
        }
        return out;
    }
    std::array<double, 3> sum{};
    for (int k = 0; k < count; ++k) {
        SpectralSample s;
        s.lambdaNm = 400.0 + 300.0 * (k + 0.5) / count;
        const auto xyz = cieXyz(s.lambdaNm);
        // XYZ to linear sRGB (IEC 61966-2-1 primaries, D65 white).
        s.weight = {3.2406 * xyz[0] - 1.5372 * xyz[1] - 0.4986 * xyz[2],
                    -0.9689 * xyz[0] + 1.8758 * xyz[1] + 0.0415 * xyz[2],
                    0.0557 * xyz[0] - 0.2040 * xyz[1] + 1.0570 * xyz[2]};
        for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += s.weight[std::size_t(c)];
        out.push_back(s);
    }
    for (SpectralSample& s : out) {
        for (int c = 0; c < 3; ++c) s.weight[std::size_t(c)] /= sum[std::size_t(c)];
    }
    return out;
}

}  // namespace flarekit::lens
