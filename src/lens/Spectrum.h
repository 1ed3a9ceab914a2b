// SPDX-License-Identifier: Apache-2.0
// The wavelengths a lens render traces and the linear-sRGB weight of each.
#pragma once

#include <array>
#include <vector>

namespace flarekit::lens {

struct SpectralSample {
    double lambdaNm = 550;
    std::array<double, 3> weight{};  //!< linear sRGB contribution; each channel sums to 1
};

//! `count` 0: the three RGB wavelengths, each feeding its own channel. Otherwise `count`
//! wavelengths at the centres of equal bins over 400-700 nm, weighted by the CIE 1931
//! colour-matching functions taken to linear sRGB and normalised so an equal-energy spectrum
//! gives white (1, 1, 1).
std::vector<SpectralSample> spectralSamples(int count);

//! CIE 1931 2-degree colour-matching functions, Wyman, Sloan & Shirley's multi-lobe fit
//! ("Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2013).
std::array<double, 3> cieXyz(double lambdaNm);

}  // namespace flarekit::lens
