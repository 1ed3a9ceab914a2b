// SPDX-License-Identifier: Apache-2.0
// Every file flarekit writes goes through writeFileSafely, so that a full disk, a signal or a
// crash never leaves a truncated file and never replaces what the user had.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "flarekit/Result.h"

namespace flarekit {

//! Writes `bytes` as the whole content of `path`:
//!  - a new or regular file: into a temporary file beside it (with the old file's permissions),
//!    every write and the close checked, fsync'd, then renamed over the target; the directory
//!    is synced so the rename survives a crash;
//!  - a symbolic link: the same at the file it points to, so the link stays a link;
//!  - a device, FIFO or socket (`/dev/null`, `/dev/stdout` on a pipe): written in place,
//!    every write checked (renaming over a device node would replace it).
//! A missing output folder is made first. Refuses to start (Interrupted) once SIGINT/SIGTERM
//! has arrived.
Status writeFileSafely(const std::string& path, std::string_view bytes);

//! Why `path` cannot be written (it is a directory, or its folder cannot be made because an
//! ancestor is a file), or Ok. A missing folder is not an error: writeFileSafely makes it.
Status checkWritablePath(const std::string& path);

//! The name every temporary file of writeFileSafely starts with.
inline constexpr std::string_view kTempFilePrefix = ".flarekit-tmp-";

//! Removes the temporary files writeFileSafely left in `dir` and its subfolders when its process
//! was killed (SIGKILL, a lost cluster worker, a power cut): only for a folder whose writers are
//! all known to be done. Returns how many were removed; best effort, never fails.
std::size_t removeOrphanTempFiles(const std::string& dir);

//! Makes the folder `dir` (and its parents) when missing; one line naming it when that fails.
Status makeOutputDirectory(const std::string& dir);

//! Flushes standard output and fails (naming it) when anything written to it was lost, e.g.
//! `flarekit visibility --json > /dev/full`.
Status flushStandardOutput();

}  // namespace flarekit
