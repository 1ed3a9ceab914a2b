// SPDX-License-Identifier: Apache-2.0
// The optics every lens computation shares: dispersion, Fresnel and multi-layer thin-film
// reflectance, the paraxial (y-nu) trace.
#include <cmath>
#include <complex>

#include "flarekit/Lens.h"

namespace flarekit {

double refractiveIndex(const LensSurface& s, double lambdaNm) {
    if (s.vd <= 0.0 || s.nd == 1.0) return s.nd;
    // Cauchy's n = A + B / lambda^2 through the d line, with the F - C difference the Abbe
    // number implies: (n_d - 1) / v_d = B (1/F^2 - 1/C^2). Good to a few 1e-4 across the
    // visible for optical glasses, which is far below what a flare's colours can show.
    const double b = (s.nd - 1.0) / (s.vd * (1.0 / (kLineF * kLineF) - 1.0 / (kLineC * kLineC)));
    const double a = s.nd - b / (kLineD * kLineD);
    return a + b / (lambdaNm * lambdaNm);
}

namespace {

using Complex = std::complex<double>;

//! Amplitude reflection coefficients (s, p) between media a and b at cosines ca, cb.
struct Amplitudes {
    Complex s, p;
};
Amplitudes fresnel(double na, Complex ca, double nb, Complex cb) {
    return {(na * ca - nb * cb) / (na * ca + nb * cb), (nb * ca - na * cb) / (nb * ca + na * cb)};
}

//! Tilted admittance of a medium of index n at cosine c: n cos for s, n / cos for p.
Complex admittance(double n, Complex c, bool p) {
    return p ? n / c : n * c;
}

}  // namespace

LensCoating coatingDesign(CoatingDesign design, double designNm) {
    switch (design) {
        case CoatingDesign::Mgf2:
            return {{quarterWave(kMgF2Index, designNm)}};
        case CoatingDesign::Broadband:
            // Quarter, half, quarter: the half-wave ZrO2 is absent at the design wavelength
            // (the stack reflects there as the two quarters alone) and flattens the curve
            // either side of it.
            return {{quarterWave(kMgF2Index, designNm),
                     {kZrO2Index, designNm / (2.0 * kZrO2Index)},
                     quarterWave(kCeF3Index, designNm)}};
    }
    return {};
}

double interfaceReflectance(double n0, double n2, double cos0, const LensCoating& coating,
                            double lambdaNm) {
    if (n0 == n2 && !coating.present()) return 0.0;
    const double sin0 = std::sqrt(std::max(0.0, 1.0 - cos0 * cos0));
    // Cosines in each medium from Snell's invariant n sin; complex past the critical angle.
    const auto cosIn = [&](double n) {
        return std::sqrt(Complex(1.0 - (n0 * sin0 / n) * (n0 * sin0 / n)));
    };
    const Complex c0 = cos0, c2 = cosIn(n2);
    if (n0 * sin0 >= n2) return 1.0;  // total internal reflection
    if (!coating.present()) {
        const Amplitudes r = fresnel(n0, c0, n2, c2);
        return 0.5 * (std::norm(r.s) + std::norm(r.p));
    }
    // The characteristic matrix of the stack (Macleod, Thin-Film Optical Filters, 2001,
    // chapter 2): each layer j multiplies [[cos d, i sin d / y], [i y sin d, cos d]], d = 2 pi
    // n_j t_j cos_j / lambda, y its tilted admittance; [B, C] = M [1, y_exit] and r = (y0 B - C)
    // / (y0 B + C). The layers are listed from the lower-index side, so the product runs from
    // n0 when n0 is that side and from n2 otherwise.
    const bool fromLow = n0 <= n2;
    double reflectance = 0.0;
    for (const bool p : {false, true}) {
        Complex m00 = 1.0, m01 = 0.0, m10 = 0.0, m11 = 1.0;
        const std::size_t count = coating.layers.size();
        for (std::size_t k = 0; k < count; ++k) {
            const CoatingLayer& layer = coating.layers[fromLow ? k : count - 1 - k];
            const Complex c = cosIn(layer.n), y = admittance(layer.n, c, p);
            const Complex delta = 2.0 * M_PI * layer.n * layer.thicknessNm * c / lambdaNm;
            const Complex cd = std::cos(delta), sd = Complex(0.0, 1.0) * std::sin(delta);
            const Complex a00 = m00 * cd + m01 * y * sd, a01 = m00 * sd / y + m01 * cd;
            const Complex a10 = m10 * cd + m11 * y * sd, a11 = m10 * sd / y + m11 * cd;
            m00 = a00, m01 = a01, m10 = a10, m11 = a11;
        }
        const Complex y0 = admittance(n0, c0, p), yExit = admittance(n2, c2, p);
        const Complex b = m00 + m01 * yExit, c = m10 + m11 * yExit;
        reflectance += 0.5 * std::norm((y0 * b - c) / (y0 * b + c));
    }
    return std::min(1.0, reflectance);
}

Paraxial paraxial(const Lens& lens, double lambdaNm) {
    // A ray parallel to the axis at height 1 (y-nu form: n'u' = nu - y phi, phi = (n' - n) c).
    double y = 1.0, u = 0.0, n = 1.0, yStop = 1.0;
    const int stop = lens.stopIndex();
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const LensSurface& s = lens.surfaces[i];
        const double n2 = refractiveIndex(s, lambdaNm);
        const double c = s.radius == 0.0 ? 0.0 : 1.0 / s.radius;
        if (int(i) == stop) yStop = y;
        u = (n * u - y * (n2 - n) * c) / n2;
        n = n2;
        if (i + 1 < lens.surfaces.size()) y += s.thickness * u;
    }
    Paraxial p;
    // Image space is air (the format has the sensor in air): f = -y0 / u' with y0 = 1.
    p.focalLength = -1.0 / u;
    p.backFocus = -y / u;
    if (stop >= 0 && yStop != 0.0)
        p.entrancePupil = lens.surfaces[std::size_t(stop)].semiAperture / std::fabs(yStop);
    p.fNumber = p.entrancePupil > 0 ? p.focalLength / (2.0 * p.entrancePupil) : 0.0;
    return p;
}

}  // namespace flarekit
