// SPDX-License-Identifier: Apache-2.0
// The plug-in's dialog: mode, preset or lens, the light (found, or placed by a click in the
// preview), intensity, threshold, new layer; a live preview of the whole image at up to 480 px.
#pragma once

#include <libgimp/gimp.h>

#include "GimpSettings.h"

namespace flarekit::gimp {

//! Shows the dialog for `drawable`; true with `settings` edited when the user pressed OK.
bool runDialog(gint32 image, gint32 drawable, Settings& settings);

}  // namespace flarekit::gimp
