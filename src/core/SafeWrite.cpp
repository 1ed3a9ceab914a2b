// SPDX-License-Identifier: Apache-2.0
#include "core/SafeWrite.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/Interrupt.h"

namespace flarekit {

namespace fs = std::filesystem;

namespace {

std::string errnoText() {
    return std::strerror(errno);
}

//! write(2) until every byte is out; false (errno set) on the first failure.
bool writeAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        bytes.remove_prefix(std::size_t(n));
    }
    return true;
}

Status writeInPlace(const std::string& path, std::string_view bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return ioError(path + ": cannot write: " + errnoText());
    const bool ok = writeAll(fd, bytes);
    const std::string why = ok ? "" : errnoText();
    if (::close(fd) != 0 && ok) return ioError(path + ": cannot write: " + errnoText());
    if (!ok) return ioError(path + ": cannot write: " + why);
    return Ok{};
}

//! fsync of the directory holding `file`, so a completed rename is on disk. Best effort: some
//! file systems refuse to sync a directory and the data itself is already synced.
void syncDirectory(const fs::path& file) {
    const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}

Status replaceAtomically(const std::string& shownPath, const fs::path& target,
                         std::string_view bytes, mode_t mode) {
    static std::atomic<int> counter{0};
    const fs::path temp =
        target.parent_path() / (std::string(kTempFilePrefix) + std::to_string(::getpid()) + "-" +
                                std::to_string(counter++) + "-" + target.filename().string());
    TrackedTempPath tracked(temp.string());
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0) return ioError(shownPath + ": cannot write: " + errnoText());
    auto fail = [&](const std::string& why) -> Status {
        ::unlink(temp.c_str());
        return ioError(shownPath + ": cannot write: " + why);
    };
    const bool written = writeAll(fd, bytes);
    const std::string writeWhy = written ? "" : errnoText();
    // fsync: delayed allocation can report a full disk only here; close can report it too.
    const bool synced = written && ::fsync(fd) == 0;
    const std::string syncWhy = synced || !written ? "" : errnoText();
    const bool closed = ::close(fd) == 0;
    if (!written) return fail(writeWhy);
    if (!synced) return fail(syncWhy);
    if (!closed) return fail(errnoText());
    if (mode != 0666) (void)::chmod(temp.c_str(), mode);  // the old file's mode, past the umask
    if (interrupted()) {
        ::unlink(temp.c_str());
        return interruptedError(shownPath + " was not written");
    }
    if (::rename(temp.c_str(), target.c_str()) != 0) return fail(errnoText());
    syncDirectory(target);
    return Ok{};
}

}  // namespace

Status checkWritablePath(const std::string& path) {
    if (path.empty()) return invalidInput("output: expected a file name, got an empty path");
    const fs::path p(path);
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    // A missing output folder is made when the file is written (makeOutputDirectory), the same
    // for every output; what must hold now is that it can be: its nearest existing ancestor is
    // a folder, not a file.
    // One stat per folder: another writer (a parallel sample, a second job) may make the folder
    // between two separate tests, which would read as "exists but is not a directory".
    for (fs::path up = dir;; up = up.parent_path()) {
        const fs::file_status st = fs::status(up, ec);
        if (fs::is_directory(st)) break;
        if (fs::exists(st))
            return invalidInput(path + ": output directory '" + dir.string() +
                                "' cannot be made: '" + up.string() + "' is not a directory");
        if (up.parent_path().empty() || up == up.parent_path()) break;
    }
    if (fs::is_directory(p, ec)) return invalidInput(path + ": output path is a directory");
    return Ok{};
}

std::size_t removeOrphanTempFiles(const std::string& dir) {
    std::size_t removed = 0;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        std::error_code typeEc;
        if (!it->is_regular_file(typeEc)) continue;
        if (!it->path().filename().string().starts_with(kTempFilePrefix)) continue;
        std::error_code removeEc;
        if (fs::remove(it->path(), removeEc)) ++removed;
    }
    return removed;
}

Status makeOutputDirectory(const std::string& dir) {
    std::error_code ec;
    if (dir.empty() || fs::is_directory(dir, ec)) return Ok{};
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec))
        return invalidInput(dir + ": cannot create the output directory" +
                            (ec ? ": " + ec.message() : ""));
    return Ok{};
}

Status writeFileSafely(const std::string& path, std::string_view bytes) {
    if (interrupted()) return interruptedError(path + " was not written");
    if (Status s = checkWritablePath(path); !s) return s;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {  // follows links: what the path finally names
        if (!S_ISREG(st.st_mode)) return writeInPlace(path, bytes);
        std::error_code ec;
        const fs::path real = fs::canonical(path, ec);  // through every symbolic link
        if (ec) return ioError(path + ": cannot write: " + ec.message());
        return replaceAtomically(path, real, bytes, st.st_mode & 07777);
    }
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        // A dangling link: create the file it names, in its own directory.
        std::error_code ec;
        fs::path to = fs::read_symlink(path, ec);
        if (ec) return ioError(path + ": cannot write: " + ec.message());
        if (to.is_relative()) to = fs::path(path).parent_path() / to;
        if (Status s = checkWritablePath(to.string()); !s) return s;
        return replaceAtomically(path, to, bytes, 0666);
    }
    if (Status s = makeOutputDirectory(fs::path(path).parent_path().string()); !s) return s;
    return replaceAtomically(path, fs::path(path), bytes, 0666);
}

Status flushStandardOutput() {
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        return ioError("standard output: cannot write: " + errnoText());
    return Ok{};
}

}  // namespace flarekit
