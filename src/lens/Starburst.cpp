// The aperture's Fraunhofer diffraction: |FFT|^2 of the iris polygon (FFTW), the point spread
// function whose spikes are the starburst, cached per aperture shape.
#include "lens/Starburst.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "lens/LensTrace.h"

namespace flarekit::lens {

namespace {

//! The pupil's radius as a share of the grid (its diameter a quarter of it): the zero padding
//! puts the first Airy zero 1.22 x 4 = 4.9 samples from the centre, so the core and the spikes'
//! fringes are resolved.
constexpr double kPupilShare = 0.125;
//! The iris edge is antialiased over this many samples, so the spikes are not aliased stairs.
constexpr double kEdgeSamples = 1.0;

std::vector<float> computePsf(const LensAperture& aperture, int n) {
    std::vector<double> pupil(std::size_t(n) * std::size_t(n));
    const double radius = kPupilShare * n;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const double px = (x - n / 2 + 0.5) / radius, py = (y - n / 2 + 0.5) / radius;
            const double q = apertureRadius(aperture, px, py);
            const double inside = std::clamp((1.0 - q) * radius / kEdgeSamples + 0.5, 0.0, 1.0);
            pupil[std::size_t(y) * std::size_t(n) + std::size_t(x)] = inside;
        }
    }
    const int half = n / 2 + 1;
    fftw_complex* spectrum = fftw_alloc_complex(std::size_t(n) * std::size_t(half));
    static std::mutex planner;  // FFTW's planner is not thread-safe; execution is
    fftw_plan plan;
    {
        std::lock_guard<std::mutex> lock(planner);
        plan = fftw_plan_dft_r2c_2d(n, n, pupil.data(), spectrum, FFTW_ESTIMATE);
    }
    fftw_execute(plan);
    std::vector<float> psf(std::size_t(n) * std::size_t(n));
    double sum = 0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            // The real transform stores half the columns; the rest mirror (Hermitian).
            const int fx = x < half ? x : n - x, fy = x < half ? y : (n - y) % n;
            const fftw_complex& c = spectrum[std::size_t(fy) * std::size_t(half) + std::size_t(fx)];
            const double power = c[0] * c[0] + c[1] * c[1];
            // Shift the zero frequency to the centre.
            const int sx = (x + n / 2) % n, sy = (y + n / 2) % n;
            psf[std::size_t(sy) * std::size_t(n) + std::size_t(sx)] = float(power);
            sum += power;
        }
    }
    for (float& v : psf) v = float(v / sum);
    {
        std::lock_guard<std::mutex> lock(planner);
        fftw_destroy_plan(plan);
    }
    fftw_free(spectrum);
    return psf;
}

}  // namespace

const Psf& aperturePsf(const LensAperture& aperture, int size) {
    static std::mutex mutex;
    static std::map<std::tuple<int, double, double, int>, Psf> cache;
    const auto key =
        std::make_tuple(aperture.blades, aperture.rotationDeg, aperture.roundness, size);
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it == cache.end()) {
        Psf p;
        p.size = size;
        p.values = computePsf(aperture, size);
        p.pupilShare = kPupilShare;
        it = cache.emplace(key, std::move(p)).first;
    }
    return it->second;
}

double samplePsf(const Psf& psf, double x, double y) {
    // x, y in PSF samples from the centre; bilinear.
    const double fx = x + psf.size / 2, fy = y + psf.size / 2;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= psf.size || y0 + 1 >= psf.size) return 0.0;
    const double tx = fx - x0, ty = fy - y0;
    const auto at = [&](int xx, int yy) {
        return double(psf.values[std::size_t(yy) * std::size_t(psf.size) + std::size_t(xx)]);
    };
    return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) +
           (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

}  // namespace flarekit::lens
