// SPDX-License-Identifier: Apache-2.0
// Where flarekit's shipped files are at run time, found from where the running code is, never
// from a path of the machine that built it: an install moved to another prefix, or unpacked
// anywhere, finds its own presets, lenses, OCIO config and image module.
#pragma once

#include <filesystem>
#include <vector>

namespace flarekit {

//! The shipped presets' root folders, best first (each holds the sprite presets, postfx/,
//! lenses/ and ocio/): $FLAREKIT_DATA_DIR, then share/flarekit/presets of the prefix of the
//! running executable, then of the shared library this code is in (libflarekit.so), then, when
//! the executable runs from flarekit's own build tree, the source tree's presets/. Only folders
//! that exist are listed.
std::vector<std::filesystem::path> shippedPresetRoots();

//! The shipped OpenColorIO config (ocio/flarekit.ocio under the first root that has it);
//! empty when none is found.
std::filesystem::path shippedOcioConfig();

//! Where libflarekit_oiio.so may be, best first: lib/flarekit/ of the executable's prefix and of
//! the shared library's, then the build tree's src/.
std::vector<std::filesystem::path> oiioModuleCandidates();

//! A front end whose code is installed elsewhere (the Python module under dist-packages) adds
//! where its install keeps the presets' root and libflarekit_oiio.so's folder; both are
//! searched after the executable's and the library's own.
void addShippedRoots(const std::filesystem::path& presets, const std::filesystem::path& modules);

}  // namespace flarekit
