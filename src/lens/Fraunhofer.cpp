// SPDX-License-Identifier: Apache-2.0
// The pupil's 2-D DFT through KissFFT's C++ template (Mark Borgerding, BSD-3-Clause), in double
// precision: Debian's compiled KissFFT is float only, and the starburst's tails sit 1e-9 below
// its core, where float's rounding would show. Rows then columns of 1-D complex transforms.
#include "lens/Fraunhofer.h"

#include <kissfft/kissfft.hh>

#include <complex>
#include <cstddef>

namespace flarekit::lens {

std::vector<double> centredPowerSpectrum(const std::vector<double>& pupil, int n) {
    using Fft = kissfft<double>;
    using Complex = Fft::cpx_t;
    const std::size_t un = std::size_t(n);
    const Fft fft(un, false);
    std::vector<Complex> in(un), out(un);
    // Each row's transform, row-major.
    std::vector<Complex> rows(un * un);
    for (std::size_t y = 0; y < un; ++y) {
        for (std::size_t x = 0; x < un; ++x) in[x] = pupil[y * un + x];
        fft.transform(in.data(), rows.data() + y * un);
    }
    // Columns 0..n/2 only: a real grid's spectrum is Hermitian, F(-u, -v) = conj F(u, v), so the
    // power of the other columns is the mirror of these.
    const std::size_t half = un / 2 + 1;
    std::vector<double> power(un * un);
    for (std::size_t u = 0; u < half; ++u) {
        for (std::size_t y = 0; y < un; ++y) in[y] = rows[y * un + u];
        fft.transform(in.data(), out.data());
        for (std::size_t v = 0; v < un; ++v) {
            const double p = std::norm(out[v]);
            // Zero frequency to the centre: frequency k lands at sample (k + n/2) mod n.
            power[((v + un / 2) % un) * un + (u + un / 2) % un] = p;
            const std::size_t mu = (un - u) % un, mv = (un - v) % un;
            if (mu >= half) power[((mv + un / 2) % un) * un + (mu + un / 2) % un] = p;
        }
    }
    return power;
}

}  // namespace flarekit::lens
