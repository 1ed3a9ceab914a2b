// SPDX-License-Identifier: Apache-2.0
// The cubic ease 3t^2 - 2t^3 on [0, 1], clamped: the soft edges of the temporal filter's frame
// border, the highlight expansion's reach and the starburst's radial window.
#pragma once

#include <algorithm>

namespace flarekit {

template <class T>
T smoothstep01(T t) {
    t = std::clamp(t, T(0), T(1));
    return t * t * (T(3) - T(2) * t);
}

}  // namespace flarekit
