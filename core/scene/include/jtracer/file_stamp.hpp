#pragma once
// What tells an unchanged file from a changed one without reading it: its size
// and modification time. Files a scene names (models, image maps) are read
// again only when their stamp moves.

#include <cstdint>
#include <filesystem>
#include <system_error>

namespace jt {

struct FileStamp {
    bool exists = false;
    std::uintmax_t size = 0;
    std::int64_t mtime_ns = 0;
    bool operator==(const FileStamp&) const = default;
};

inline FileStamp file_stamp(const std::filesystem::path& path) {
    std::error_code error;
    FileStamp s;
    s.size = std::filesystem::file_size(path, error);
    if (error) return {};
    const auto time = std::filesystem::last_write_time(path, error);
    if (error) return {};
    s.exists = true;
    s.mtime_ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
    return s;
}

}  // namespace jt
