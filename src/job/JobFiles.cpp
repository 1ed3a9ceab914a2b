// SPDX-License-Identifier: Apache-2.0
// Every file a job will write, checked against every file it reads and against the others it
// writes, before any work: a layer named like the plate, an output pattern over its input
// frames, a composite over one of its own layers would otherwise replace what the user had.
#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <optional>

#include "core/SafeWrite.h"
#include "flarekit/job/Job.h"
#include "job/LayerFiles.h"

namespace flarekit {

namespace {

//! What makes two paths one file. The name with links, `.` and `..` resolved catches a file
//! not yet written; the device and inode catch a hard link or a second mount of one folder.
struct FileIdentity {
    std::string name;
    std::optional<std::pair<dev_t, ino_t>> inode;
};

//! Nothing for a device, FIFO or socket: `-o /dev/null` twice is not a clash.
std::optional<FileIdentity> identityOf(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    FileIdentity id;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    id.name = ec ? fs::absolute(path).lexically_normal().string() : resolved.string();
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (!S_ISREG(st.st_mode)) return std::nullopt;
        id.inode = std::pair{st.st_dev, st.st_ino};
    }
    return id;
}

std::string describe(const JobFile& file) {
    return file.role + " " + file.path;
}

}  // namespace

Status checkJobFiles(const std::vector<JobFile>& reads, const std::vector<JobFile>& writes) {
    // Each file by both keys; the first claim on a key wins.
    std::map<std::string, const JobFile*> byName;
    std::map<std::pair<dev_t, ino_t>, const JobFile*> byInode;
    auto claim = [&](const JobFile& file, bool written) -> Status {
        const auto id = identityOf(file.path);
        // A read that is not there yet cannot be lost (the job fails on it later anyway).
        if (!id || (!written && !id->inode)) return Ok{};
        const JobFile* other = nullptr;
        if (auto it = byName.find(id->name); it != byName.end()) other = it->second;
        if (id->inode && !other)
            if (auto it = byInode.find(*id->inode); it != byInode.end()) other = it->second;
        if (other && written)
            return invalidInput(file.path + ": " + file.role + " would be written over " +
                                describe(*other) + " (the same file); write it elsewhere");
        byName.emplace(id->name, &file);
        if (id->inode) byInode.emplace(*id->inode, &file);
        return Ok{};
    };
    for (const JobFile& file : reads)
        if (Status s = claim(file, false); !s) return s;
    for (const JobFile& file : writes)
        if (Status s = claim(file, true); !s) return s;
    return Ok{};
}

namespace job_detail {

Status writeLayerFiles(const std::string& dir, const std::vector<LayerFile>& files,
                       const WriteOptions& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool made = !fs::exists(dir, ec);
    if (Status s = makeOutputDirectory(dir); !s) return s;
    std::string written;
    for (std::size_t i = 0; i < files.size(); ++i) {
        Status s = writeImage(files[i].first, *files[i].second, options);
        if (s) {
            written += (written.empty() ? "" : ", ") + fs::path(files[i].first).filename().string();
            continue;
        }
        std::string missing;
        for (std::size_t k = i; k < files.size(); ++k)
            missing += (missing.empty() ? "" : ", ") + fs::path(files[k].first).filename().string();
        if (made && fs::is_empty(dir, ec)) fs::remove(dir, ec);
        Error e = s.error();
        e.message += "; layers in " + dir + ": " +
                     (written.empty() ? std::string("none written") : written + " written") +
                     ", not written: " + missing;
        return e;
    }
    return Ok{};
}

}  // namespace job_detail

}  // namespace flarekit
