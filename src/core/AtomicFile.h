// Atomic output: every file flarekit writes goes to a temporary name in the same directory and
// is renamed over the target only once complete, so a failure never leaves a partial file.
#pragma once

#include <functional>
#include <string>

#include "flarekit/Result.h"

namespace flarekit {

//! Calls write(tempPath) and renames tempPath to path when it succeeds; removes tempPath
//! otherwise. The temporary name keeps path's extension so format detection still works.
Status writeAtomically(const std::string& path,
                       const std::function<Status(const std::string&)>& write);

}  // namespace flarekit
