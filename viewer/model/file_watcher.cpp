#include "model/file_watcher.hpp"

#include <algorithm>

namespace jt::view {

void FileWatcher::watch(const std::filesystem::path& path) {
    path_ = path;
    seen_ = file_stamp(path_);
    last_check_ = Clock::now();
}

bool FileWatcher::poll(Clock::time_point now) {
    if (path_.empty() || now - last_check_ < interval_) return false;
    last_check_ = now;
    const FileStamp current = file_stamp(path_);
    if (current == seen_) return false;
    seen_ = current;
    return true;
}

void FileWatcher::acknowledge() {
    seen_ = file_stamp(path_);
}

void FileSetWatcher::watch(const std::vector<std::filesystem::path>& files) {
    std::vector<std::pair<std::filesystem::path, FileStamp>> next;
    next.reserve(files.size());
    for (const std::filesystem::path& file : files) {
        const auto known = std::find_if(seen_.begin(), seen_.end(),
                                        [&](const auto& entry) { return entry.first == file; });
        next.emplace_back(file, known != seen_.end() ? known->second : file_stamp(file));
    }
    seen_ = std::move(next);
}

std::vector<std::filesystem::path> FileSetWatcher::poll(Clock::time_point now) {
    std::vector<std::filesystem::path> changed;
    if (!due(now)) return changed;
    last_check_ = now;
    for (auto& [file, seen] : seen_) {
        const FileStamp current = file_stamp(file);
        if (current == seen) continue;
        seen = current;
        changed.push_back(file);
    }
    return changed;
}

void FileSetWatcher::acknowledge() {
    for (auto& [file, seen] : seen_) seen = file_stamp(file);
}

}  // namespace jt::view
