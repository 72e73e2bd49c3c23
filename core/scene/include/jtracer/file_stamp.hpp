#pragma once
// What tells an unchanged file from a changed one without reading it: its
// identity (inode), size and modification time. Editors that save by writing
// a new file and renaming it over the old one change the inode even when size
// and time look the same. Files a scene names (models, image maps) are read
// again, and the viewer reloads its scene, only when their stamp moves.

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>

namespace jt {

struct FileStamp {
    bool exists = false;
    std::uint64_t inode = 0;
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    bool operator==(const FileStamp&) const = default;
};

inline FileStamp file_stamp(const struct stat& info) {
    FileStamp stamp;
    stamp.exists = true;
    stamp.inode = static_cast<std::uint64_t>(info.st_ino);
    stamp.size = static_cast<std::uint64_t>(info.st_size);
    stamp.mtime_ns = static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1'000'000'000 +
                     static_cast<std::int64_t>(info.st_mtim.tv_nsec);
    return stamp;
}

inline FileStamp file_stamp(const std::filesystem::path& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return {};
    return file_stamp(info);
}

// The stamp of an open file, whatever its name now leads to.
inline FileStamp file_stamp(int descriptor) {
    struct stat info {};
    if (::fstat(descriptor, &info) != 0) return {};
    return file_stamp(info);
}

}  // namespace jt
