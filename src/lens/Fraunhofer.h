// SPDX-License-Identifier: Apache-2.0
// The power spectrum of a real pupil grid (see Fraunhofer.cpp).
#pragma once

#include <vector>

namespace flarekit::lens {

//! |DFT|^2 of the n x n real grid `pupil` (row-major), unnormalised, with the zero frequency
//! moved to sample (n/2, n/2): the far-field (Fraunhofer) intensity of that pupil.
std::vector<double> centredPowerSpectrum(const std::vector<double>& pupil, int n);

}  // namespace flarekit::lens
