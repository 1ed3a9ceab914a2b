// SPDX-License-Identifier: Apache-2.0
// A GIMP drawable through flarekit: its pixels read as linear RGBA floats through GEGL (GIMP's
// own conversion from the image's precision, 8-bit to 32-bit float), flared by the library's
// pixel job, and written back at the image's precision, onto the drawable or as a new layer.
#pragma once

#include <libgimp/gimp.h>

#include "GimpSettings.h"
#include "HostFlare.h"
#include "flarekit/job/Job.h"

namespace flarekit::gimp {

//! The drawable's pixels, `scale` of their size (the dialog's preview; 1: all of them).
Result<PixelInput> readDrawable(gint32 image, gint32 drawable, double scale = 1.0);

//! The request the settings make for a drawable whose image pixels are `scale` of the image's
//! (the light given in image coordinates, moved by the drawable's offsets).
host::FlareRequest flareRequest(const Settings& settings, gint32 drawable, double scale = 1.0);

//! Runs the settings on the drawable inside one undo group.
Status flareDrawable(gint32 image, gint32 drawable, const Settings& settings,
                     const JobEvents& events = {});

}  // namespace flarekit::gimp
