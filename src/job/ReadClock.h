// SPDX-License-Identifier: Apache-2.0
// Seconds a shot's frames spent reading their inputs, summed over the threads: the read share of
// the summary a shot returns (ShotSummary). readJobInput adds to it, runShot resets and reads it.
#pragma once

namespace flarekit::job_detail {

void addReadSeconds(double seconds);
//! The sum since the last reset, and a reset.
double takeReadSeconds();

}  // namespace flarekit::job_detail
