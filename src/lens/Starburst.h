// The iris's diffraction pattern (see Starburst.cpp).
#pragma once

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

//! The PSF of an iris shape, computed once per shape and size in the process.
const Psf& aperturePsf(const LensAperture& aperture, int size);
//! Bilinear sample at (x, y) samples from the centre; 0 outside.
double samplePsf(const Psf& psf, double x, double y);

}  // namespace flarekit::lens
