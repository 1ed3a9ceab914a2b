// SPDX-License-Identifier: Apache-2.0
// A value one GPU pass leaves for the next in a channel of a 1x1 texture (the sun's coverage,
// the flare weight, the adapted exposure): the typed handle the GL classes pass each other so
// the CPU never reads it, instead of a bare texture name and a channel index.
#pragma once

namespace flarekit {

struct GpuChannel {
    unsigned texture =
        0;            //!< GL texture name; 0: no value (readers use their default, e.g. exposure 1)
    int channel = 0;  //!< 0..3: red, green, blue, alpha
    explicit operator bool() const { return texture != 0; }
};

}  // namespace flarekit
