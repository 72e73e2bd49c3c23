#pragma once
// Notices when files change on disk: the scene file (FileWatcher) and the
// model and image files it names (FileSetWatcher). Both poll the files'
// stamps (jtracer/file_stamp.hpp), at most once per interval.

#include "jtracer/file_stamp.hpp"

#include <chrono>
#include <filesystem>
#include <utility>
#include <vector>

namespace jt::view {

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

class FileSetWatcher {
  public:
    using Clock = std::chrono::steady_clock;
    explicit FileSetWatcher(Clock::duration interval = std::chrono::milliseconds(200))
        : interval_(interval) {}

    // True when the interval since the last poll has passed.
    bool due(Clock::time_point now = Clock::now()) const { return now - last_check_ >= interval_; }
    // Watches exactly `files` from now on. A file watched before keeps the
    // state last seen (so a change made meanwhile is still reported); a new
    // one counts as seen as it is now.
    void watch(const std::vector<std::filesystem::path>& files);
    // The watched files that changed since the last poll (or since they were
    // first watched), each once; empty before the interval has passed.
    std::vector<std::filesystem::path> poll(Clock::time_point now = Clock::now());
    // Takes every watched file's current state as seen, e.g. after saving them ourselves.
    void acknowledge();
    const std::vector<std::pair<std::filesystem::path, FileStamp>>& files() const { return seen_; }

  private:
    std::vector<std::pair<std::filesystem::path, FileStamp>> seen_;
    Clock::duration interval_;
    Clock::time_point last_check_{};
};

}  // namespace jt::view
