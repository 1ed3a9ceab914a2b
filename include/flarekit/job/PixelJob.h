// SPDX-License-Identifier: Apache-2.0
// The jobs on pixels a front end already holds (the Python module's arrays, the studio's
// image, a host application's buffer): the same work as the file jobs of ApplyJob.h,
// PostFxJob.h and LensJob.h on one image, minus the reading and writing. The options' file
// fields (input, output, layers folder, part) are not used; everything else means what it
// means for a file, and the result is what that job writes to a float EXR.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PostFxJob.h"

namespace flarekit {

//! An image in the working space (linear Rec.709 RGBA floats).
struct PixelInput {
    Image image;
    //! The pixels came from an 8/16-bit (display-referred) image: white is the display's, so
    //! its clipped lights are expanded where a job does that for 8/16-bit files (the light
    //! finder's white core, --expand-highlights). False: scene-linear HDR data.
    bool displayReferred = false;
    bool hasAlpha = true;        //!< the alpha channel means something (kept as it is either way)
    std::string name = "image";  //!< how messages name the image
};

//! A job's result: the image as its float EXR output would hold it, and its passes (each the
//! input's size, linear) by the names their layer files have.
struct PixelOutput {
    Image image;
    std::vector<std::pair<std::string, Image>> layers;
};

//! `flarekit apply` on pixels. A matte (options.occlusion) names files and is refused here.
//! `keepLayers`: each pass of the preset and the whole flare.
Result<PixelOutput> applyPixels(const ApplyOptions& options, PixelInput input,
                                const JobEvents& events = {}, bool keepLayers = false);
//! The same with a preset held in memory (an editor's, checked with validatePreset); the
//! options' `preset` only names it in messages.
Result<PixelOutput> applyPixels(const ApplyOptions& options, const Preset& preset, PixelInput input,
                                const JobEvents& events = {}, bool keepLayers = false);
//! `flarekit postfx` on pixels; `keepLayers`: bloom, ghosts, halo, streaks, lens.
Result<PixelOutput> postFxPixels(const PostFxJobOptions& options, PixelInput input,
                                 const JobEvents& events = {}, bool keepLayers = false);
//! `flarekit lens render` on pixels; `keepLayers`: ghosts, starburst, glare, flare.
Result<PixelOutput> lensPixels(const LensJobOptions& options, PixelInput input,
                               const JobEvents& events = {}, bool keepLayers = false);

}  // namespace flarekit
