// Tone mapping of linear HDR for display (8/16-bit outputs). Float outputs stay linear.
#pragma once

#include "flarekit/Image.h"

namespace flarekit {

//! Krzysztof Narkowicz's fit of the ACES filmic curve (2015),
//! f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), applied per channel to
//! exposure x colour; the result is in [0, 1] (linear, before sRGB encoding).
void tonemapAcesFitted(Image& image, float exposure);

}  // namespace flarekit
