#pragma once
// What the scene converters (jts-to-pov, jts-to-tachyon) share: loading the
// scene exactly as JTracer does, building the output text, writing it safely,
// and the z mirror that both left-handed renderers need.

#include "jtracer/atomic_file.hpp"
#include "jtracer/scene_file.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace jt::bench {

inline constexpr int exit_scene_errors = 1, exit_usage = 2, exit_io = 3;

// POV-Ray and Tachyon are left-handed: every point and direction is mirrored
// in z (S = diag(1, 1, -1)), which shows the same picture.
inline Vec3 mirror_z(const Vec3& v) {
    return {v.x, v.y, -v.z};
}

class TextWriter {
  public:
    void printf(const char* format, ...) __attribute__((format(printf, 2, 3))) {
        char buffer[512];
        va_list args;
        va_start(args, format);
        int n = std::vsnprintf(buffer, sizeof buffer, format, args);
        va_end(args);
        if (n > 0)
            text_.append(buffer, static_cast<std::size_t>(std::min<int>(n, sizeof buffer - 1)));
    }
    // `v` as "<x, y, z>" after `prefix` (POV-Ray's vector syntax).
    void vector(const char* prefix, const Vec3& v) {
        printf("%s<%.9g, %.9g, %.9g>", prefix, v.x, v.y, v.z);
    }
    // `v` as "x y z" after `prefix` (Tachyon's).
    void triple(const char* prefix, const Vec3& v) {
        printf("%s%.9g %.9g %.9g", prefix, v.x, v.y, v.z);
    }
    const std::string& text() const { return text_; }

  private:
    std::string text_;
};

// The scene at `path`, read and checked as jtracer-cli does. On failure the
// reason is on stderr (prefixed by `program`) and `exit_code` is set.
inline std::optional<LoadedScene> load_checked_scene(const char* program, const char* path,
                                                     int& exit_code) {
    Expected<LoadedScene> read = load_scene_file(path);
    if (!read) {
        std::cerr << program << ": " << read.error().message << "\n";
        exit_code = exit_io;
        return std::nullopt;
    }
    auto diagnostics = check_scene(*read);
    if (has_errors(diagnostics)) {
        std::cerr << format_diagnostics(diagnostics, *read);
        exit_code = exit_scene_errors;
        return std::nullopt;
    }
    return std::move(*read);
}

// Writes `text` through a temporary file; false (with the reason on stderr) if
// that failed.
inline bool write_text(const char* program, const std::string& path, const std::string& text) {
    const Expected<void> written = write_file_atomically(
        path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    if (!written) std::cerr << program << ": " << written.error().message << "\n";
    return static_cast<bool>(written);
}

}  // namespace jt::bench
