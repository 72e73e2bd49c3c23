#include "file_watcher.hpp"

#include <sys/stat.h>

namespace jt::view {

FileStamp stamp_file(const std::filesystem::path& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return {};
    FileStamp stamp;
    stamp.exists = true;
    stamp.inode = static_cast<std::uint64_t>(info.st_ino);
    stamp.size = static_cast<std::uint64_t>(info.st_size);
    stamp.mtime_ns = static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1'000'000'000 +
                     static_cast<std::int64_t>(info.st_mtim.tv_nsec);
    return stamp;
}

void FileWatcher::watch(const std::filesystem::path& path) {
    path_ = path;
    seen_ = stamp_file(path_);
    last_check_ = Clock::now();
}

bool FileWatcher::poll(Clock::time_point now) {
    if (path_.empty() || now - last_check_ < interval_) return false;
    last_check_ = now;
    const FileStamp current = stamp_file(path_);
    if (current == seen_) return false;
    seen_ = current;
    return true;
}

void FileWatcher::acknowledge() {
    seen_ = stamp_file(path_);
}

}  // namespace jt::view
