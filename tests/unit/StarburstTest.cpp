// SPDX-License-Identifier: Apache-2.0
// The starburst's diffraction pattern on KissFFT against two references that do not use it: a
// direct double-precision DFT of small grids (powers of two and mixed radices), and values the
// same PSF had when FFTW computed it (kept below), within 1e-5 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "lens/Fraunhofer.h"
#include "lens/Starburst.h"

using namespace flarekit;

namespace {

//! |sum_x,y g(x, y) e^{-2 pi i (u x + v y) / n}|^2 straight from the definition, O(n^4).
std::vector<double> directPower(const std::vector<double>& g, int n) {
    std::vector<double> power(std::size_t(n) * std::size_t(n));
    for (int v = 0; v < n; ++v) {
        for (int u = 0; u < n; ++u) {
            std::complex<double> sum = 0;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const double phase = -2 * std::numbers::pi * double((u * x + v * y) % n) / n;
                    sum += g[std::size_t(y * n + x)] * std::polar(1.0, phase);
                }
            // Zero frequency at (n/2, n/2), as the PSF stores it.
            const int sx = (u + n / 2) % n, sy = (v + n / 2) % n;
            power[std::size_t(sy * n + sx)] = std::norm(sum);
        }
    }
    return power;
}

}  // namespace

TEST(Starburst, PowerSpectrumIsTheDirectDft) {
    for (const int n : {8, 16, 12, 15, 30}) {
        // A disc (the symmetric case) and random values (no symmetry to hide a mirroring slip).
        std::vector<double> disc(std::size_t(n) * std::size_t(n)), noise(disc.size());
        unsigned state = 12345u + unsigned(n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double r = std::hypot(x - n / 2 + 0.5, y - n / 2 + 0.5);
                disc[std::size_t(y * n + x)] = std::clamp(n / 4.0 - r + 0.5, 0.0, 1.0);
                state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
                noise[std::size_t(y * n + x)] = double(state >> 8) / double(1u << 24);
            }
        for (const auto* grid : {&disc, &noise}) {
            const std::vector<double> fast = lens::centredPowerSpectrum(*grid, n);
            const std::vector<double> slow = directPower(*grid, n);
            double peak = 0;
            for (double p : slow) peak = std::max(peak, p);
            for (std::size_t i = 0; i < slow.size(); ++i)
                ASSERT_NEAR(fast[i], slow[i], 1e-12 * peak + 1e-9 * slow[i])
                    << "n " << n << " sample " << i % std::size_t(n) << "," << i / std::size_t(n);
        }
    }
}

TEST(Starburst, ThePsfIsWhatFftwGave) {
    // aperturePsf(aperture, dirt with seed 7, 512) as FFTW 3.3.10's real 2-D transform computed
    // it before the move to KissFFT, at these offsets from the centre (x right, y down).
    const int offsets[][2] = {{0, 0},     {1, 0},       {0, 3},    {5, 2},      {17, 0},
                              {40, 9},    {-33, 61},    {100, -7}, {-200, 150}, {3, -250},
                              {255, 255}, {-256, -256}, {12, -40}, {80, 80}};
    struct Case {
        LensAperture aperture;
        double dirt;
        double values[14];
    };
    const Case cases[] = {
        {{6, 15.0, 0.0},
         0.0,
         {4.076936096e-02, 3.580528498e-02, 1.118940488e-02, 1.579000013e-06, 6.368401228e-05,
          3.303419192e-07, 9.616258900e-09, 4.545588084e-08, 1.068099942e-09, 1.229913615e-09,
          9.919155275e-08, 3.069034449e-07, 9.497792064e-08, 2.942104175e-06}},
        {{7, 0.0, 0.3},
         0.5,
         {4.186895490e-02, 3.629754856e-02, 9.957216680e-03, 5.141534712e-05, 1.734908801e-05,
          1.145472925e-05, 1.760312784e-06, 5.571833981e-07, 9.884526087e-09, 3.624276346e-08,
          8.918567218e-09, 5.151016058e-09, 1.513653297e-05, 4.411147358e-07}},
        {{0, 0.0, 0.0},
         0.0,
         {4.933039472e-02, 4.219469056e-02, 9.956132621e-03, 2.436001960e-04, 4.782419794e-08,
          8.378810423e-10, 6.900753391e-08, 6.322549950e-08, 2.259235909e-09, 1.406244010e-08,
          5.593832619e-10, 0.0, 1.153486551e-06, 2.029638013e-09}},
    };
    for (const Case& c : cases) {
        lens::PupilDirt dirt;
        dirt.amount = c.dirt;
        dirt.seed = 7;
        const lens::Psf& psf = lens::aperturePsf(c.aperture, dirt, 512);
        ASSERT_EQ(psf.size, 512);
        for (int k = 0; k < 14; ++k) {
            const std::size_t i =
                std::size_t(offsets[k][1] + 256) * 512 + std::size_t(offsets[k][0] + 256);
            // The stored values have 10 significant digits; 1e-5 relative, and 1e-15 absolute
            // for the circle's Nyquist corner, which is zero up to rounding.
            EXPECT_NEAR(psf.values[i], c.values[k], 1e-5 * c.values[k] + 1e-15)
                << c.aperture.blades << " blades, offset " << offsets[k][0] << "," << offsets[k][1];
        }
    }
}
