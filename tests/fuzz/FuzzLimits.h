// SPDX-License-Identifier: Apache-2.0
// Every fuzz target runs under a 512 MiB memory budget: an input that would need more must be
// refused by the budget check, and libFuzzer's -rss_limit_mb (3072; FuzzImageRead's own RSS
// reaches ~1.7 GB under ASan) catches any allocation the checks miss.
#pragma once

#include "flarekit/Limits.h"

namespace flarekit::fuzz {

inline void setLimits() {
    static const bool done = [] {
        ResourceLimits limits;
        limits.maxMemoryBytes = std::uint64_t(512) << 20;
        setResourceLimits(limits);
        return true;
    }();
    (void)done;
}

}  // namespace flarekit::fuzz
