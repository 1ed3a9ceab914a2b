// SPDX-License-Identifier: Apache-2.0
// libflarekit.so's own translation unit: the library is the C API of flarekit.h, whose
// entry points (engine/CApi.cpp) come in whole from flarekit_gl (cmake/Package.cmake). This
// file only records the version the library was built as, for fk_version().
#include "flarekit/flarekit.h"

extern "C" FK_API int fk_version(void) {
    return FK_VERSION_MAJOR * 10000 + FK_VERSION_MINOR * 100;
}
