// SPDX-License-Identifier: Apache-2.0
// An in-memory job's pixels as the image its file job would have read (flarekit/job/PixelJob.h).
#pragma once

#include "flarekit/job/PixelJob.h"

namespace flarekit::job_detail {

//! `input` as a job's read image: its peak (`job` per pixel) checked against the memory budget,
//! NaN and infinities replaced as a file's are (a warning through `events`).
Result<LoadedImage> loadedFromPixels(PixelInput&& input, const JobMemory& job,
                                     const JobEvents& events);

}  // namespace flarekit::job_detail
