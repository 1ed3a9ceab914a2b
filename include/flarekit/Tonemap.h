// SPDX-License-Identifier: Apache-2.0
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

//! Where highlight expansion starts: the largest channel of a display-referred pixel above
//! 0.8 linear (sRGB 231), the shoulder a camera's tone curve compresses hardest.
inline constexpr float kExpandKnee = 0.8f;
//! `postfx --expand-highlights`: an inverse tone curve for 8/16-bit input, whose lights are
//! clipped at 1. A pixel's colour is multiplied by 1 + (gain - 1) s^2, s the position of its
//! largest channel between kExpandKnee and 1, so values below the knee are untouched, the curve
//! leaves the knee smoothly and a clipped pixel becomes `gain` x white: what the light likely
//! was before the camera clipped it.
void expandHighlights(Image& image, float gain);

}  // namespace flarekit
