#include "core/AtomicFile.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <system_error>

namespace flarekit {

namespace fs = std::filesystem;

std::string firstLine(const std::string& text) {
    std::size_t begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return {};
    std::size_t end = text.find_first_of("\r\n", begin);
    std::string line = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
    return line;
}

Status writeAtomically(const std::string& path, const std::function<Status(const std::string&)>& write) {
    static std::atomic<int> counter{0};
    const fs::path target(path);
    const fs::path temp = target.parent_path() /
                          (".flarekit-tmp-" + std::to_string(::getpid()) + "-" +
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
