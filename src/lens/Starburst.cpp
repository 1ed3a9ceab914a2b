// SPDX-License-Identifier: Apache-2.0
// The aperture's Fraunhofer diffraction: |FFT|^2 of the iris polygon (lens/Fraunhofer.h), the
// point spread function whose spikes are the starburst, cached per aperture shape.
#include "lens/Starburst.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <tuple>

#include "core/Random.h"
#include "flarekit/Color.h"
#include "lens/Fraunhofer.h"
#include "lens/LensTrace.h"

namespace flarekit::lens {

namespace {

//! The pupil's radius as a share of the grid (its diameter a quarter of it): the zero padding
//! puts the first Airy zero 1.22 x 4 = 4.9 samples from the centre, so the core and the spikes'
//! fringes are resolved.
constexpr double kPupilShare = 0.125;
//! The iris edge is antialiased over this many samples, so the spikes are not aliased stairs.
constexpr double kEdgeSamples = 1.0;

//! Specks and scratches at full dirt; their sizes are shares of the pupil's radius. Dust on a
//! rear element is out of focus at the iris, so it darkens soft discs rather than points.
constexpr int kMaxSpecks = 400, kMaxScratches = 8;
constexpr double kSpeckMin = 0.01, kSpeckMax = 0.04, kScratchWidth = 0.004;

//! Multiplies the pupil by opaque specks and thin scratches.
void addDirt(std::vector<double>& pupil, int n, double radius, const PupilDirt& dirt) {
    if (dirt.amount <= 0) return;
    SplitMix64 rng(dirt.seed);
    const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.nextFloat(); };
    const auto shade = [&](int x, int y, double opacity) {
        if (x < 0 || y < 0 || x >= n || y >= n) return;
        pupil[std::size_t(y) * std::size_t(n) + std::size_t(x)] *= 1.0 - opacity;
    };
    const int specks = int(std::lround(kMaxSpecks * dirt.amount));
    for (int k = 0; k < specks; ++k) {
        const double cx = n / 2 + uniform(-1, 1) * radius, cy = n / 2 + uniform(-1, 1) * radius;
        const double r = uniform(kSpeckMin, kSpeckMax) * radius;
        for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y) {
            for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x) {
                const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                shade(x, y, 0.8 * std::clamp(r + 0.5 - d, 0.0, 1.0));
            }
        }
    }
    const int scratches = int(std::lround(kMaxScratches * dirt.amount));
    for (int k = 0; k < scratches; ++k) {
        const double angle = uniform(0, M_PI), length = uniform(0.3, 1.2) * radius;
        const double cx = n / 2 + uniform(-0.6, 0.6) * radius,
                     cy = n / 2 + uniform(-0.6, 0.6) * radius;
        const double w = std::max(0.5, kScratchWidth * radius);
        const int steps = int(length * 2);
        for (int i = 0; i <= steps; ++i) {
            const double t = (double(i) / steps - 0.5) * length;
            const double px = cx + t * std::cos(angle), py = cy + t * std::sin(angle);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const double d = std::hypot(dx, dy);
                    shade(int(px) + dx, int(py) + dy, 0.5 * std::clamp(w + 0.5 - d, 0.0, 1.0));
                }
        }
    }
}

//! Multiplies the pupil by the mask's luminance (clamped to [0, 1]), bilinear, the image
//! stretched over the stop circle's bounding square.
void applyMask(std::vector<double>& pupil, int n, double radius, const Image& mask) {
    if (mask.width() < 1 || mask.height() < 1) return;
    const auto transmission = [&](int x, int y) {
        const Rgba& p =
            mask.at(std::clamp(x, 0, mask.width() - 1), std::clamp(y, 0, mask.height() - 1));
        return std::clamp(double(luminance(p.r, p.g, p.b)), 0.0, 1.0);
    };
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            // The pupil point in [-1, 1]^2 of the stop's radius, then in mask pixels (centres at
            // +0.5); grid row 0 is the top of the iris.
            const double px = (x - n / 2 + 0.5) / radius, py = (y - n / 2 + 0.5) / radius;
            if (std::fabs(px) > 1 || std::fabs(py) > 1) continue;
            const double u = (px + 1) / 2 * mask.width() - 0.5,
                         v = (py + 1) / 2 * mask.height() - 0.5;
            const int u0 = int(std::floor(u)), v0 = int(std::floor(v));
            const double tu = u - u0, tv = v - v0;
            const double t =
                (transmission(u0, v0) * (1 - tu) + transmission(u0 + 1, v0) * tu) * (1 - tv) +
                (transmission(u0, v0 + 1) * (1 - tu) + transmission(u0 + 1, v0 + 1) * tu) * tv;
            pupil[std::size_t(y) * std::size_t(n) + std::size_t(x)] *= t;
        }
    }
}

std::vector<float> computePsf(const LensAperture& aperture, const PupilDirt& dirt, int n) {
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
    addDirt(pupil, n, radius, dirt);
    if (dirt.mask) applyMask(pupil, n, radius, *dirt.mask);
    const std::vector<double> power = centredPowerSpectrum(pupil, n);
    double sum = 0;
    for (double p : power) sum += p;
    std::vector<float> psf(power.size());
    for (std::size_t i = 0; i < power.size(); ++i) psf[i] = float(power[i] / sum);
    return psf;
}

}  // namespace

std::uint64_t pupilMaskHash(const Image& mask) {
    // FNV-1a (Fowler, Noll and Vo) with its 64-bit offset basis and prime, taken a pixel's
    // two 8-byte halves at a time rather than byte by byte: a 4K mask is hashed per render.
    std::uint64_t h = 14695981039346656037ull;
    const auto add = [&](std::uint64_t word) { h = (h ^ word) * 1099511628211ull; };
    add(std::uint64_t(mask.width()) << 32 | std::uint64_t(mask.height()));
    const float* f = mask.data();
    for (std::size_t i = 0; i < mask.pixelCount() * 4; i += 2) {
        std::uint64_t word = 0;
        std::memcpy(&word, f + i, sizeof word);
        add(word);
    }
    return h;
}

const Psf& aperturePsf(const LensAperture& aperture, const PupilDirt& dirt, int size) {
    static std::mutex mutex;
    static std::map<std::tuple<int, double, double, double, std::uint32_t, std::uint64_t, int>, Psf>
        cache;
    const auto key = std::make_tuple(aperture.blades, aperture.rotationDeg, aperture.roundness,
                                     dirt.amount, dirt.seed, dirt.mask ? dirt.maskHash : 0, size);
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it == cache.end()) {
        Psf p;
        p.size = size;
        p.values = computePsf(aperture, dirt, size);
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
