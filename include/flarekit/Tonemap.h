// Tone mapping of linear HDR for display (8/16-bit outputs). Float outputs stay linear.
#pragma once

#include "flarekit/Image.h"
#include "flarekit/PostFxParams.h"

namespace flarekit {

//! Krzysztof Narkowicz's fit of the ACES filmic curve (2015),
//! f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), applied per channel to
//! exposure x colour; the result is in [0, 1] (linear, before sRGB encoding).
void tonemapAcesFitted(Image& image, float exposure);

//! The display transform of `apply` and `render`: exposure x colour through `op` (none: just
//! the exposure, values above 1 kept for float outputs; aces; filmic, Hable 2010), per channel,
//! alpha untouched.
void toneMapImage(Image& image, ToneOperator op, float exposure);

}  // namespace flarekit
