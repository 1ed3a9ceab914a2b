// SPDX-License-Identifier: Apache-2.0
// The iris's diffraction pattern (see Starburst.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "flarekit/Lens.h"

namespace flarekit::lens {

//! |FFT|^2 of the pupil on a size x size grid, zero frequency at the centre, summing to 1. The
//! pupil's radius is pupilShare x size samples, so sample k from the centre is the spatial
//! frequency k / (size x sample pitch): at wavelength lambda it lands lambda x f x that
//! frequency from the image of the source (Fraunhofer).
struct Psf {
    int size = 0;
    double pupilShare = 0;
    std::vector<float> values;
};

//! Dust and scratches on the iris plane: `amount` 0 is clean, 1 a badly kept lens (400 specks,
//! 8 scratches); the same seed gives the same pattern everywhere. `mask`, when given, is the
//! plane's transmission from an image (LensRenderOptions::pupilMask), `maskHash` its content's
//! hash (pupilMaskHash), which keys the PSF cache.
struct PupilDirt {
    double amount = 0;
    std::uint32_t seed = 1;
    const Image* mask = nullptr;
    std::uint64_t maskHash = 0;
};

//! FNV-1a over the mask's size and pixels: two masks with the same pixels share a PSF.
std::uint64_t pupilMaskHash(const Image& mask);

//! The PSF of an iris shape (with its dirt), computed once per shape, dirt and size in the
//! process.
const Psf& aperturePsf(const LensAperture& aperture, const PupilDirt& dirt, int size);
//! Bilinear sample at (x, y) samples from the centre; 0 outside.
double samplePsf(const Psf& psf, double x, double y);

}  // namespace flarekit::lens
