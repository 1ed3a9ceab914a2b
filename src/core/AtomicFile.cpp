#include "core/AtomicFile.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <system_error>

namespace flarekit {

namespace fs = std::filesystem;

Status writeAtomically(const std::string& path,
                       const std::function<Status(const std::string&)>& write) {
    static std::atomic<int> counter{0};
    const fs::path target(path);
    const fs::path temp =
        target.parent_path() / (".flarekit-tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(counter++) + "-" + target.filename().string());
    Status written = write(temp.string());
    std::error_code ec;
    if (!written.ok()) {
        fs::remove(temp, ec);
        return written;
    }
    fs::rename(temp, target, ec);
    if (ec) {
        fs::remove(temp, ec);
        return ioError(path + ": cannot write: " + ec.message());
    }
    return Ok{};
}

}  // namespace flarekit
