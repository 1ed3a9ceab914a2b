// SPDX-License-Identifier: Apache-2.0
// The optics every lens computation shares: dispersion, Fresnel and thin-film reflectance, the
// paraxial (y-nu) trace.
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

}  // namespace

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
    // One layer (index n1, thickness d) between n0 and n2: the two interfaces' amplitudes
    // summed over all internal bounces (Airy), r = (r01 + r12 e^{-2i delta}) /
    // (1 + r01 r12 e^{-2i delta}), delta = 2 pi n1 d cos1 / lambda (Born & Wolf, Principles of
    // Optics, 1959, section 1.6).
    const double n1 = coating.n;
    const Complex c1 = cosIn(n1);
    const Amplitudes r01 = fresnel(n0, c0, n1, c1), r12 = fresnel(n1, c1, n2, c2);
    const Complex phase =
        std::exp(Complex(0.0, -2.0) * (2.0 * M_PI * n1 * coating.thicknessNm / lambdaNm) * c1);
    const Complex rs = (r01.s + r12.s * phase) / (1.0 + r01.s * r12.s * phase);
    const Complex rp = (r01.p + r12.p * phase) / (1.0 + r01.p * r12.p * phase);
    return std::min(1.0, 0.5 * (std::norm(rs) + std::norm(rp)));
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
