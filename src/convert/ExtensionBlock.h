// SPDX-License-Identifier: Apache-2.0
// The "flarekit" key a JSON engine format carries beside an element it cannot describe fully
// (a ring's width, a glow's inner colour, a procedural element baked into a texture): the
// flarekit element's own keys, so that reading the file back gives the element flarekit wrote.
// Babylon.js's and PlayCanvas's loaders ignore keys they do not know.
#pragma once

#include "convert/ConvertCommon.h"

namespace flarekit::convert {

//! The element's keys as a flarekit preset writes them (without `texture`).
json elementExtension(const ElementParams& e);
//! The element an extension block describes (validated as a preset's element would be), or
//! an error naming `at`.
Result<ElementParams> elementFromExtension(const json& block, const JsonPlace& at);

}  // namespace flarekit::convert
