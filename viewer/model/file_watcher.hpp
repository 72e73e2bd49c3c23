#pragma once
// Notices when the scene file changes on disk. Polls the file's identity
// (inode), size and modification time: editors that save by writing a new file
// and renaming it over the old one change the inode even when size and time
// look the same.

#include <chrono>
#include <cstdint>
#include <filesystem>

namespace jt::view {

struct FileStamp {
    bool exists = false;
    std::uint64_t inode = 0;
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    bool operator==(const FileStamp&) const = default;
};

FileStamp stamp_file(const std::filesystem::path& path);

class FileWatcher {
  public:
    using Clock = std::chrono::steady_clock;
    explicit FileWatcher(Clock::duration interval = std::chrono::milliseconds(200))
        : interval_(interval) {}

    // Starts watching `path`; its current state counts as seen.
    void watch(const std::filesystem::path& path);
    // True once for each change since the last poll (or watch/acknowledge).
    // Checks the disk at most once per interval.
    bool poll(Clock::time_point now = Clock::now());
    // Takes the file's current state as seen, e.g. after saving it ourselves.
    void acknowledge();
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    FileStamp seen_;
    Clock::duration interval_;
    Clock::time_point last_check_{};
};

}  // namespace jt::view
