// SPDX-License-Identifier: Apache-2.0
// A job's layers as files of their own (`--layers DIR`, `--save-layers DIR`): one writer for
// apply, postfx and lens render, so a failure or a signal half-way says the same thing in each.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "flarekit/ImageIO.h"

namespace flarekit::job_detail {

//! A layer's file and its image.
using LayerFile = std::pair<std::string, const Image*>;

//! Writes `files` in order, each atomically, into their folder `dir` (made when missing). When
//! one fails (a full disk, a signal) the error says which files were written and complete and
//! which were not, and a folder this call made is removed again while nothing is in it.
Status writeLayerFiles(const std::string& dir, const std::vector<LayerFile>& files,
                       const WriteOptions& options);

}  // namespace flarekit::job_detail
