#pragma once
// The most recently opened scene files, newest first, kept in a small text file
// (one path a line) so they survive restarts.

#include <filesystem>
#include <string>
#include <vector>

namespace jt::view {

class RecentFiles {
  public:
    static constexpr std::size_t capacity = 10;

    // Reads the list from `storage` (a missing or unreadable file is an empty
    // list). An empty path keeps the list in memory only.
    void load(const std::filesystem::path& storage);
    // Moves `path` to the front and writes the list back.
    void add(const std::filesystem::path& path);
    const std::vector<std::string>& paths() const { return paths_; }

  private:
    std::filesystem::path storage_;
    std::vector<std::string> paths_;
};

// config_folder()/recent-scenes.txt (viewer_settings.hpp), or empty.
std::filesystem::path default_recent_files_path();

}  // namespace jt::view
