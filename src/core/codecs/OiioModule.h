// SPDX-License-Identifier: Apache-2.0
// The OpenImageIO module: every format flarekit does not run itself (Radiance HDR, BMP, TGA,
// PPM, WebP, DPX, BigTIFF, layered EXR, CMYK JPEG, palette TIFF, ...) and the contact sheet's
// text. It is a shared object of flarekit's own build (libflarekit_oiio.so) opened with dlopen
// the first time it is needed, so that a run that never meets such a file never loads
// OpenImageIO and its 263 libraries (a quarter of a second and 130 MB before main).
#pragma once

#include <string>
#include <vector>

#include "core/codecs/Codec.h"

namespace flarekit::codec {

//! Bumped whenever this interface changes: a module of another build is not used.
inline constexpr int kOiioModuleAbi = 1;

struct OiioModule {
    int abi = kOiioModuleAbi;
    std::size_t rawSize = sizeof(Raw);
    std::size_t samplesSize = sizeof(Samples);
    //! Reads the first image of any file OpenImageIO knows (straight alpha kept), calling check
    //! before the pixels are allocated. Videos are refused.
    Result<Raw> (*read)(const std::string& path, const HeaderCheck& check);
    //! Whether the format of path's extension can be encoded into memory; `alpha`: it holds one.
    bool (*canWrite)(const std::string& path, bool* alpha);
    //! Encodes samples in the format of path's extension (integer samples tagged sRGB when
    //! s.srgb, float samples linear).
    Result<std::vector<unsigned char>> (*encode)(const std::string& path, const Samples& s);
    //! Draws text into float RGBA pixels with the TrueType font at fontPath.
    bool (*renderText)(float* rgba, int width, int height, int x, int y, const std::string& text,
                       int size, const std::string& fontPath, const float colour[4]);
};

//! The labels' font (the element contact sheet, the lens sheet): Debian's fonts-dejavu-core,
//! installed by scripts/install-deps.sh.
inline constexpr const char* kLabelFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

//! The module, opened on first use; nullptr with the reason in `why` when it cannot be loaded.
const OiioModule* oiioModule(std::string* why = nullptr);

}  // namespace flarekit::codec

//! The module's one exported symbol.
extern "C" const flarekit::codec::OiioModule* flarekit_oiio_module();
