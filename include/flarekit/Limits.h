// SPDX-License-Identifier: Apache-2.0
// The resource budget every job is checked against before it allocates: a memory limit (what a
// job's peak is estimated to need, from file headers and options), the ratio of pixels to file
// bytes above which an image is taken for a decompression bomb, and a cap on a flare's
// per-pixel shading work. The CLI sets it from --max-memory / FLAREKIT_MAX_MEMORY.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "flarekit/Result.h"

namespace flarekit {

struct ResourceLimits {
    //! 4 GiB: a 2-core, 8 GiB build or CI machine keeps half its memory for the system, and
    //! every shipped job at 8K fits (apply and the CPU postfx need about 50 bytes per pixel).
    std::uint64_t maxMemoryBytes = std::uint64_t(4) << 30;
    //! Pixels per byte of file above which a large image is refused as a decompression bomb.
    //! Deflate compresses at most about 1032:1, so a uniform 1-bit PNG reaches ~8,300 pixels per
    //! byte and any 8-bit or deeper file far less; a header claiming 16384x16384 in 1.7 KB (a
    //! TIFF whose strips all point at one block) has 158,000.
    double maxPixelsPerFileByte = 10000;
    //! Images up to this many pixels are never refused by the ratio: their decoded size (at
    //! most 256 MiB as float RGBA) is harmless whatever the file claims.
    std::uint64_t ratioCheckFromPixels = std::uint64_t(1) << 24;
};

//! The process-wide limits (defaults until setResourceLimits).
ResourceLimits resourceLimits();
void setResourceLimits(const ResourceLimits& limits);

//! Fails when `bytes`, a job's estimated peak, exceeds the memory budget: "what: needs an
//! estimated 12.9 GiB (detail), over the memory budget of 4 GiB (raise it with --max-memory or
//! FLAREKIT_MAX_MEMORY)".
Status checkMemory(const std::string& what, double bytes, const std::string& detail = {});
//! "12.9 GiB", "640 MiB", "512 bytes".
std::string formatBytes(double bytes);
//! "4G", "4GiB", "512M", "800MB", "65536" (bytes); binary units. nullopt when malformed.
std::optional<std::uint64_t> parseByteSize(std::string_view text);

}  // namespace flarekit
